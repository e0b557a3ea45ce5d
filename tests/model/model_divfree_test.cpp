// DIVFREE against the exact quotient of its own plane equations: on every pixel where the cap was not
// hit it selects the exact cell (for nearest: the texel of nearest sampling); on a pixel where the cap
// stopped the walk it takes the cell of the RECIP_NR divider's coordinate, which lies within the
// divider's error bound of the exact quotient (no wild texels); the cap bounds the steps, and cap
// hits stay rare on every scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "htx/fw/vertex_record.h"
#include "htx/model/geometry.hpp"
#include "htx/model/lod.hpp"
#include "htx/model/model.hpp"
#include "htx/model/perspective.hpp"
#include "htx/model/recip.hpp"
#include "htx/model/scenes.hpp"
#include "htx/model/texture.hpp"

namespace htx {
namespace {

const std::string kScenes[] = {"floor",   "cube",   "tunnel", "wsweep", "nearclip",
                               "slivers", "bigtri", "wrap",   "pan",    "randmesh"};

ScreenScene divfree_scene(const std::string& name, Filter filter) {
  ScreenScene s = prepare_screen_scene(make_builtin_scene(name), 320, 240);
  for (ScreenTri& t : s.tris) {
    t.state.method = Method::DivFree;
    t.state.filter = filter;
  }
  return s;
}

model::RecipParams pixel_divider(const ModelConfig& cfg) {
  return {cfg.recip_table_bits, cfg.recip_guard_bits, cfg.recip_width, cfg.pixel_nr_steps};
}

// Relative error bound of the RECIP_NR reciprocal: the table's DasSarma-Matula bound
// 2^-(k+1) (1 + 2^-(g+1)), squared by every Newton step, plus an allowance of 2^-(W-2) per step for
// the datapath's truncations.
double divider_relative_bound(const ModelConfig& cfg) {
  double e = std::ldexp(1.0 + std::ldexp(1.0, -static_cast<int>(cfg.recip_guard_bits) - 1),
                        -static_cast<int>(cfg.recip_table_bits) - 1);
  for (unsigned s = 0; s < cfg.pixel_nr_steps; ++s) e = e * e + std::ldexp(1.0, 2 - static_cast<int>(cfg.recip_width));
  return e;
}

struct Tally {
  uint64_t pixels = 0, capped = 0;
  uint64_t mismatches = 0;        // uncapped pixels off the exact cell (or, nearest, the exact texel)
  uint64_t not_divided = 0;       // capped axes off both the exact cell and the divided value's cell
  uint64_t beyond_divider = 0;    // divided coordinates outside the divider's bound
  uint64_t wild = 0;              // capped axes more than one cell from the exact cell
  uint64_t off_one = 0;           // capped axes one cell off (the divider's error crossed a cell edge)
  uint64_t steps_over_cap = 0;    // pixels with more than 2 * cap steps
  double worst_divider_ulps = 0;  // largest |divided - exact| in units of the bound
};

// Walks every triangle through the raster unit (with the LOD unit and level range render_model
// gives it) and checks each pixel against the exact quotient of its planes.
Tally check_scene(const ScreenScene& sc, const ModelConfig& cfg) {
  Tally t;
  const unsigned tf = cfg.texcoord_frac_bits;
  const model::Log2Unit log2_unit(cfg.lod_log_index_bits, cfg.lod_frac_bits + 2);
  const model::RecipParams divider = pixel_divider(cfg);
  const double rel = divider_relative_bound(cfg);
  model::SpanCoords span;
  for (const ScreenTri& tri : sc.tris) {
    if (!tri.state.textured) continue;
    fw::VertexIn in[3];
    for (int k = 0; k < 3; ++k) {
      const ScreenVertex& v = tri.v[k];
      in[k].x = v.x, in[k].y = v.y, in[k].z = v.z, in[k].w = v.w, in[k].u = v.u, in[k].v = v.v;
    }
    fw::TriangleRecord rec;
    if (fw::encode_triangle(cfg.record_format(), in, &rec) != fw::kEncodeOk) continue;
    const Texture& tex = sc.textures[static_cast<size_t>(tri.state.texture)];
    const model::TriangleUnit unit(rec, tri.state, cfg, sc.width, sc.height, &log2_unit, level_count(tex) - 1);
    if (unit.empty()) continue;
    const unsigned f = unit.divfree_grid_bits();
    for (int y = unit.y_lo(); y <= unit.y_hi(); ++y) {
      int x0, x1;
      if (!unit.span(y, &x0, &x1)) continue;
      unit.span_coords(y, x0, x1, Method::DivFree, &span);
      const unsigned level = span.divfree_level;
      const unsigned p_bits = tf + level - f;  // fraction bits of a cell in a coordinate
      for (int x = x0; x <= x1; ++x) {
        const size_t k = static_cast<size_t>(x - x0);
        ++t.pixels;
        if (span.divfree_steps[k] > 2 * cfg.divfree_cap) ++t.steps_over_cap;
        const bool capped = span.divfree_capped[k] != 0;
        t.capped += capped;
        const int64_t px = 256 * int64_t{x} + 128, py = 256 * int64_t{y} + 128;
        const model::i128 q = std::max<model::i128>(unit.q_plane().at(px, py), 1);
        const model::i128 num[2] = {unit.uq_plane().at(px, py), unit.vq_plane().at(px, py)};
        const int64_t coord[2] = {span.u[k], span.v[k]};
        for (int axis = 0; axis < 2; ++axis) {
          // DIVFREE outputs cell centres (2j + 1) 2^(P-1).
          const int64_t j = coord[axis] >> p_bits;
          const int64_t exact = model::divfree_exact_index(num[axis], q, f, level, p_bits);
          if (!capped) {
            if (j != exact) ++t.mismatches;
            if (f == 0 && level == 0) {
              // Nearest, independently: the sampler's rule (ceil - 1) on the coordinate gives texel i
              // iff i < round(u) <= i + 1 for the exact u = U / Q rounded to TF bits, i.e.
              // N = 2^(TF+1) U - (2^(TF+1) i + 1) Q >= 0 and M = 2^(TF+1) U - (2^(TF+1) (i+1) + 1) Q < 0.
              const int64_t i = (coord[axis] - 1) >> tf;
              const model::i128 s = static_cast<model::i128>(1) << (tf + 1);
              const bool ok = s * num[axis] - (s * i + 1) * q >= 0 && s * num[axis] - (s * (i + 1) + 1) * q < 0;
              if (!ok) ++t.mismatches;
            }
            continue;
          }
          const int64_t c = model::divide_fixed(divider, num[axis], q, tf);
          const long double x_exact = static_cast<long double>(num[axis]) * std::ldexp(1.0L, static_cast<int>(tf)) /
                                      static_cast<long double>(q);
          const long double bound = rel * std::fabs(x_exact) + 2;  // two roundings of one ulp at most
          const long double err = std::fabs(static_cast<long double>(c) - x_exact);
          t.worst_divider_ulps = std::max(t.worst_divider_ulps, static_cast<double>(err / bound));
          if (err > bound) ++t.beyond_divider;
          if (j != exact && j != ((c - 1) >> p_bits)) ++t.not_divided;
          if (j > exact + 1 || j < exact - 1) ++t.wild;
          if (j == exact + 1 || j == exact - 1) ++t.off_one;
        }
      }
    }
  }
  return t;
}

void expect_stable(const Tally& t, const std::string& what) {
  EXPECT_GT(t.pixels, 1000u) << what;
  EXPECT_EQ(t.mismatches, 0u) << what;
  EXPECT_EQ(t.not_divided, 0u) << what;
  EXPECT_EQ(t.beyond_divider, 0u) << what << " (worst " << t.worst_divider_ulps << " of the bound)";
  EXPECT_EQ(t.wild, 0u) << what;
  EXPECT_EQ(t.steps_over_cap, 0u) << what;
}

class DivfreeScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(DivfreeScenes, SelectsTheExactNearestTexelWhereverTheCapWasNotHit) {
  for (const char* cfg_name : {"full", "icebreaker"}) {
    const ModelConfig& cfg = model_config(cfg_name);
    const Tally t = check_scene(divfree_scene(GetParam(), Filter::Nearest), cfg);
    expect_stable(t, cfg_name);
    // Capped pixels stay rare (the ref comparison allows 0.1 % of wrong texels).
    EXPECT_LE(t.capped * 1000, t.pixels) << cfg_name << ": " << t.capped << " of " << t.pixels;
  }
}

TEST_P(DivfreeScenes, ExactOnTheLevelGridWithBilinearAndTrilinear) {
  for (const char* cfg_name : {"full", "icebreaker"}) {
    const ModelConfig& cfg = model_config(cfg_name);
    for (Filter f : {Filter::Bilinear, Filter::Trilinear}) {
      if (!cfg.has_filter(f)) continue;
      const std::string what = std::string(cfg_name) + (f == Filter::Bilinear ? " bilinear" : " trilinear");
      const Tally t = check_scene(divfree_scene(GetParam(), f), cfg);
      expect_stable(t, what);
      // Even on the finer 2^-f grid cap hits stay rare, thin triangles included.
      EXPECT_LE(t.capped * 1000, t.pixels) << what << ": " << t.capped << " of " << t.pixels;
    }
  }
}

TEST_P(DivfreeScenes, CapBoundsTheStepsOfEveryFilter) {
  for (const char* cfg_name : {"full", "icebreaker"}) {
    const ModelConfig& cfg = model_config(cfg_name);
    for (Filter f : {Filter::Nearest, Filter::Bilinear, Filter::Trilinear}) {
      if (!cfg.has_filter(f)) continue;
      const Frame fr = render_model(divfree_scene(GetParam(), f), cfg);
      EXPECT_GT(fr.counters.divfree_pixels, 0u);
      EXPECT_LE(fr.counters.divfree_steps_max, 2u * cfg.divfree_cap) << cfg_name;
      // The predictions leave about one grid step per pixel (measured 0.2 to 1.15 on every scene).
      EXPECT_LE(fr.counters.divfree_steps_total, 2 * fr.counters.divfree_pixels) << cfg_name;
    }
  }
}

// With a tiny cap the walk is stopped on many pixels, often many in a row; each takes the divided
// value and the walk resumes from it, so every pixel stays within the divider's bound.
TEST_P(DivfreeScenes, ASmallCapIsHitAndEveryPixelStaysBounded) {
  for (const char* cfg_name : {"full", "icebreaker"}) {
    for (unsigned cap : {1u, 4u}) {
      ModelConfig cfg = model_config(cfg_name);
      cfg.divfree_cap = cap;
      for (Filter f : {Filter::Nearest, Filter::Bilinear}) {
        const std::string what =
            std::string(cfg_name) + " cap " + std::to_string(cap) + (f == Filter::Nearest ? " nearest" : " bilinear");
        const Tally t = check_scene(divfree_scene(GetParam(), f), cfg);
        std::printf(
            "%s %s: %llu of %llu pixels capped, %llu capped axes one cell off, divided values within %.3f "
            "of the divider's bound\n",
            GetParam().c_str(), what.c_str(), static_cast<unsigned long long>(t.capped),
            static_cast<unsigned long long>(t.pixels), static_cast<unsigned long long>(t.off_one),
            t.worst_divider_ulps);
        expect_stable(t, what);
        if (cap == 1 && GetParam() == "floor") {
          EXPECT_GT(t.capped, 0u) << what;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, DivfreeScenes, ::testing::ValuesIn(kScenes));

TEST(Divfree, CapHitsCountAndBoundTheSteps) {
  ModelConfig cfg = model_config("full");
  cfg.divfree_cap = 1;
  const Frame fr = render_model(divfree_scene("floor", Filter::Nearest), cfg);
  EXPECT_GT(fr.counters.divfree_cap_hits, 0u);
  EXPECT_LE(fr.counters.divfree_steps_max, 2u);
}

TEST(Divfree, ExactIndexMatchesTheConditions) {
  // Cell j holds x - 2^-(P+1) in [j, j+1): exact ties (x = 3.0) go to the lower cell, and so does
  // anything that rounds to the tie at P fraction bits.
  EXPECT_EQ(model::divfree_exact_index(30, 10, 0, 0, 16), 2);  // u = 3.0 exactly: cell 2
  EXPECT_EQ(model::divfree_exact_index(31, 10, 0, 0, 16), 3);
  EXPECT_EQ(model::divfree_exact_index(-1, 10, 0, 0, 16), -1);   // u = -0.1
  EXPECT_EQ(model::divfree_exact_index(-10, 10, 0, 0, 16), -2);  // u = -1.0: cell -2
  EXPECT_EQ(model::divfree_exact_index(31, 10, 4, 0, 12), 49);   // 3.1 * 16 = 49.6
  EXPECT_EQ(model::divfree_exact_index(31, 10, 0, 1, 16), 1);    // level 1: 1.55
  // 3 + 2^-18 rounds to 3.0 at 16 bits (a tie: lower), 3 + 2^-16 does not.
  EXPECT_EQ(model::divfree_exact_index((int64_t{3} << 18) + 1, int64_t{1} << 18, 0, 0, 16), 2);
  EXPECT_EQ(model::divfree_exact_index((int64_t{3} << 16) + 1, int64_t{1} << 16, 0, 0, 16), 3);
}

TEST(Divfree, TheDividedCellMatchesTheExactIndexAwayFromCellEdges) {
  // The cell of a coordinate c is (c - 1) >> P, the same rule as the exact index: with an exact
  // division both agree on every value, including exact ties.
  const ModelConfig& cfg = model_config("full");
  const model::RecipParams divider = pixel_divider(cfg);
  const unsigned tf = cfg.texcoord_frac_bits;
  for (int64_t num : {30, 31, -1, -10, 29, 1000, -999}) {
    const int64_t c = model::divide_fixed(divider, num, 10, tf);
    EXPECT_EQ((c - 1) >> tf, model::divfree_exact_index(num, 10, 0, 0, tf)) << num;
    EXPECT_EQ((c - 1) >> (tf - 4), model::divfree_exact_index(num, 10, 4, 0, tf - 4)) << num;
  }
}

}  // namespace
}  // namespace htx
