// DIVFREE: on every pixel where the cap was not hit, the texel it selects is the nearest texel of
// the exact quotient of its own plane equations; the cap bounds the steps on every scene.
#include <gtest/gtest.h>

#include <string>

#include "htx/fw/vertex_record.h"
#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/perspective.hpp"
#include "htx/model/scenes.hpp"

namespace htx {
namespace {

ScreenScene divfree_scene(const std::string& name, Filter filter) {
  ScreenScene s = prepare_screen_scene(make_builtin_scene(name), 320, 240);
  for (ScreenTri& t : s.tris) {
    t.state.method = Method::DivFree;
    t.state.filter = filter;
  }
  return s;
}

struct Tally {
  uint64_t pixels = 0, capped = 0, mismatches = 0;
};

// Walks every triangle through the raster unit and checks each uncapped pixel's texel against the
// exact quotient u = U / Q of its planes rounded to the coordinate's TF fraction bits (round half
// up), sampled nearest (ceil - 1): texel i iff i < round(u) <= i + 1, i.e. in integers
// N = 2^(TF+1) U - (2^(TF+1) i + 1) Q >= 0 and M = 2^(TF+1) U - (2^(TF+1) (i+1) + 1) Q < 0.
Tally check_scene(const ScreenScene& sc, const ModelConfig& cfg) {
  Tally t;
  const unsigned tf = cfg.texcoord_frac_bits;
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
    const model::TriangleUnit unit(rec, tri.state, cfg, sc.width, sc.height);
    if (unit.empty()) continue;
    for (int y = unit.y_lo(); y <= unit.y_hi(); ++y) {
      int x0, x1;
      if (!unit.span(y, &x0, &x1)) continue;
      unit.span_coords(y, x0, x1, Method::DivFree, &span);
      for (int x = x0; x <= x1; ++x) {
        const size_t k = static_cast<size_t>(x - x0);
        ++t.pixels;
        EXPECT_LE(span.divfree_steps[k], 2 * cfg.divfree_cap);
        if (span.divfree_capped[k]) {
          ++t.capped;
          continue;
        }
        const int64_t px = 256 * int64_t{x} + 128, py = 256 * int64_t{y} + 128;
        const model::i128 q = unit.q_plane().at(px, py);
        const model::i128 num[2] = {unit.uq_plane().at(px, py), unit.vq_plane().at(px, py)};
        const int64_t coord[2] = {span.u[k], span.v[k]};
        for (int axis = 0; axis < 2; ++axis) {
          const int64_t i = (coord[axis] - 1) >> tf;  // the sampler's nearest rule, ceil(u) - 1
          const model::i128 s = static_cast<model::i128>(1) << (tf + 1);
          const bool ok = s * num[axis] - (s * i + 1) * q >= 0 && s * num[axis] - (s * (i + 1) + 1) * q < 0;
          if (!ok) ++t.mismatches;
        }
      }
    }
  }
  return t;
}

class DivfreeScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(DivfreeScenes, SelectsTheExactNearestTexelWhereverTheCapWasNotHit) {
  for (const char* cfg_name : {"full", "icebreaker"}) {
    const ModelConfig& cfg = model_config(cfg_name);
    const Tally t = check_scene(divfree_scene(GetParam(), Filter::Nearest), cfg);
    EXPECT_EQ(t.mismatches, 0u) << cfg_name;
    EXPECT_GT(t.pixels, 1000u) << cfg_name;
    // Capped pixels stay rare (the ref comparison allows 0.1 % of wrong texels).
    EXPECT_LE(t.capped * 1000, t.pixels) << cfg_name << ": " << t.capped << " of " << t.pixels;
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
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, DivfreeScenes,
                         ::testing::Values("floor", "cube", "tunnel", "wsweep", "nearclip", "slivers", "bigtri", "wrap",
                                           "pan", "randmesh"));

TEST(Divfree, ASmallCapIsHitAndStillBoundsTheSteps) {
  ModelConfig cfg = model_config("full");
  cfg.divfree_cap = 1;
  const ScreenScene sc = divfree_scene("floor", Filter::Nearest);
  const Frame fr = render_model(sc, cfg);
  EXPECT_GT(fr.counters.divfree_cap_hits, 0u);
  EXPECT_LE(fr.counters.divfree_steps_max, 2u);
  const Tally t = check_scene(sc, cfg);
  EXPECT_EQ(t.mismatches, 0u);
  EXPECT_GT(t.capped, 0u);
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

}  // namespace
}  // namespace htx
