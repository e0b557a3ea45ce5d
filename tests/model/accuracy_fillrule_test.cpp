// Fill rule: every pixel centre inside a closed mesh's silhouette is covered exactly once (no gaps,
// no overlaps), none outside, over more than 100,000 triangles, in `ref` and in `model`.
//
// Meshes: `randmesh` convex hulls (their front faces tile the silhouette, which is the 2D convex
// hull of the projected vertices), and screen-space grid triangulations whose vertices and edges
// sit on pixel centres (every tie of the top-left rule occurs). The model's per-pixel count comes
// from its counters: with the depth test off, fragments == covered pixels means nothing was hit
// twice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "htx/model/config.hpp"
#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/proc_textures.hpp"
#include "htx/model/ref.hpp"
#include "htx/model/scenes.hpp"

namespace htx {
namespace {

struct P2 {
  int64_t x, y;  // 1/256 pixel
};

int64_t cross(P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain; counter-clockwise in (x right, y down) means cross > 0 turns.
std::vector<P2> hull2d(std::vector<P2> p) {
  std::sort(p.begin(), p.end(), [](P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end(), [](P2 a, P2 b) { return a.x == b.x && a.y == b.y; }), p.end());
  std::vector<P2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

enum class Where { Inside, Boundary, Outside };

Where classify(const std::vector<P2>& hull, P2 c) {
  bool on_edge = false;
  for (size_t i = 0; i < hull.size(); ++i) {
    const int64_t e = cross(hull[i], hull[(i + 1) % hull.size()], c);
    if (e < 0) return Where::Outside;
    if (e == 0) on_edge = true;
  }
  return on_edge ? Where::Boundary : Where::Inside;
}

struct Tally {
  uint64_t triangles = 0, inside = 0, gaps = 0, overlaps = 0, outside_drawn = 0, mismatches = 0;
};

// Checks one screen scene whose triangles tile the polygon `hull` (given in 1/256 pixel).
void check_tiling(const ScreenScene& s, const std::vector<P2>& hull, Tally& ref_t, Tally& model_t) {
  const auto count = ref_coverage_count(s);
  const Frame mf = render_model(s, model_config("full"));
  uint64_t model_covered = 0;
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const size_t idx = static_cast<size_t>(j) * static_cast<size_t>(s.width) + static_cast<size_t>(i);
      const Where w = classify(hull, {256 * int64_t{i} + 128, 256 * int64_t{j} + 128});
      const unsigned c = count[idx];
      const bool m = mf.probe[idx].covered;
      model_covered += m;
      if (w == Where::Inside) {
        ++ref_t.inside;
        ++model_t.inside;
        ref_t.gaps += c == 0;
        model_t.gaps += !m;
      }
      if (w == Where::Outside) {
        ref_t.outside_drawn += c != 0;
        model_t.outside_drawn += m;
      }
      ref_t.overlaps += c > 1 ? c - 1 : 0;
      model_t.mismatches += m != (c != 0);
    }
  model_t.overlaps += mf.counters.fragments - model_covered;
  ref_t.triangles += s.tris.size();
  model_t.triangles += s.tris.size();
}

void force_state(ScreenScene& s) {
  for (ScreenTri& t : s.tris) {
    t.state.depth_func = DepthFunc::Always;
    t.state.depth_write = false;
    t.state.textured = true;
    t.state.texture = 0;
    t.state.method = Method::Affine;
    t.state.filter = Filter::Nearest;
  }
}

TEST(AccuracyFillRule, RandomClosedMeshesCoverSilhouetteExactlyOnceInRefAndModel) {
  Tally ref_t, model_t;
  int meshes = 0, skipped = 0;
  for (int seed = 1; ref_t.triangles < 100000; ++seed) {
    ASSERT_LT(seed, 2000) << "not enough triangles generated";
    const int points = 40 + (seed % 12) * 60;
    ScreenScene s = prepare_screen_scene(
        make_builtin_scene("randmesh:seed=" + std::to_string(seed) + ",count=1,points=" + std::to_string(points)),
        128, 96);
    force_state(s);
    std::vector<P2> verts;
    int64_t front_area = 0;
    for (const ScreenTri& t : s.tris) {
      P2 p[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = {static_cast<int64_t>(t.v[k].x * 256), static_cast<int64_t>(t.v[k].y * 256)};
        verts.push_back(p[k]);
      }
      front_area += std::llabs(cross(p[0], p[1], p[2]));
    }
    const std::vector<P2> hull = hull2d(verts);
    int64_t hull_area = 0;
    for (size_t i = 1; i + 1 < hull.size(); ++i) hull_area += cross(hull[0], hull[i], hull[i + 1]);
    ++meshes;
    // Snapping to 1/256 pixel can fold a silhouette sliver; such an input is no tiling to test.
    if (front_area != hull_area) {
      ++skipped;
      continue;
    }
    check_tiling(s, hull, ref_t, model_t);
  }
  RecordProperty("triangles", static_cast<int>(ref_t.triangles));
  std::printf("meshes %d (skipped %d as folded by snapping), triangles %llu, inside pixels %llu\n", meshes, skipped,
              static_cast<unsigned long long>(ref_t.triangles), static_cast<unsigned long long>(ref_t.inside));
  EXPECT_GE(ref_t.triangles, 100000u);
  EXPECT_LE(skipped * 20, meshes);  // the input generator must mostly produce valid tilings
  EXPECT_EQ(ref_t.gaps, 0u);
  EXPECT_EQ(ref_t.overlaps, 0u);
  EXPECT_EQ(ref_t.outside_drawn, 0u);
  EXPECT_EQ(model_t.gaps, 0u);
  EXPECT_EQ(model_t.overlaps, 0u);
  EXPECT_EQ(model_t.outside_drawn, 0u);
  EXPECT_EQ(model_t.mismatches, 0u) << "model and ref coverage differ";
}

TEST(AccuracyFillRule, GridTriangulationsWithEdgesThroughPixelCentres) {
  // A rectangle of cells whose corners are pixel centres jittered by whole and half pixels, each cell
  // split along a random diagonal with a random vertex order: vertices, edges and shared edges pass
  // exactly through pixel centres, so every tie of the top-left rule is exercised.
  Tally ref_t, model_t;
  uint64_t state = 12345;
  auto rnd = [&](int n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<int>((state >> 33) % static_cast<uint64_t>(n));
  };
  for (int frame = 0; frame < 8; ++frame) {
    ScreenScene s;
    s.width = 160;
    s.height = 120;
    s.textures.push_back(gradient_texture(TexFormat::RGB565, 6));
    const int nx = 18, ny = 13, cell = 8, ox = 4 + frame, oy = 3 + frame;  // corners at ox + cell*i (+0.5)
    std::vector<std::vector<P2>> g(ny + 1, std::vector<P2>(nx + 1));
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        // Interior corners move by -2..+2 pixels in half-pixel steps: on pixel centres or midway.
        const bool interior = i > 0 && i < nx && j > 0 && j < ny;
        const int hx = interior ? rnd(9) - 4 : 0, hy = interior ? rnd(9) - 4 : 0;
        g[j][i] = {(2 * (ox + cell * i) + 1 + hx) * 128, (2 * (oy + cell * j) + 1 + hy) * 128};
      }
    auto vtx = [](P2 p) {
      ScreenVertex v;
      v.x = static_cast<double>(p.x) / 256;
      v.y = static_cast<double>(p.y) / 256;
      v.u = v.x;
      v.v = v.y;
      return v;
    };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const P2 a = g[j][i], b = g[j][i + 1], c = g[j + 1][i + 1], d = g[j + 1][i];
        const bool diag = rnd(2);
        const P2 t1[3] = {a, b, diag ? c : d}, t2[3] = {diag ? a : b, c, d};
        for (const P2* t : {t1, t2}) {
          ScreenTri st;
          const int r = rnd(3), flip = rnd(2);
          for (int k = 0; k < 3; ++k) st.v[static_cast<size_t>(k)] = vtx(t[(r + (flip ? 3 - k : k)) % 3]);
          s.tris.push_back(st);
        }
      }
    force_state(s);
    // The boundary corners stay put, so the silhouette is the outer rectangle.
    check_tiling(s, hull2d({g[0][0], g[0][nx], g[ny][nx], g[ny][0]}), ref_t, model_t);
  }
  EXPECT_GT(ref_t.triangles, 1000u);
  EXPECT_EQ(ref_t.gaps, 0u);
  EXPECT_EQ(ref_t.overlaps, 0u);
  EXPECT_EQ(ref_t.outside_drawn, 0u);
  EXPECT_EQ(model_t.gaps, 0u);
  EXPECT_EQ(model_t.overlaps, 0u);
  EXPECT_EQ(model_t.outside_drawn, 0u);
  EXPECT_EQ(model_t.mismatches, 0u) << "model and ref coverage differ";
}

}  // namespace
}  // namespace htx
