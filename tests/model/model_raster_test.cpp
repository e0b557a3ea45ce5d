// Raster unit coverage: top-left fill rule on hand-made meshes (shared edges drawn exactly once),
// both windings, zero-area, off-screen and larger-than-screen triangles, vertex encoding.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/model.hpp"
#include "htx/model/raster_setup.hpp"

namespace htx {
namespace {

constexpr int kW = 64, kH = 48;

fw::TriangleRecord encode(double x0, double y0, double x1, double y1, double x2, double y2) {
  fw::VertexIn in[3];
  in[0].x = x0, in[0].y = y0;
  in[1].x = x1, in[1].y = y1;
  in[2].x = x2, in[2].y = y2;
  fw::TriangleRecord r;
  EXPECT_EQ(fw::encode_triangle(model_config("full").record_format(), in, &r), fw::kEncodeOk);
  return r;
}

// Adds the triangle's coverage to counts (one per pixel it covers), through the raster unit's setup
// and span functions.
void cover(std::vector<int>& counts, const fw::TriangleRecord& r) {
  const model::TriSetup s = model::setup_coverage(r, kW, kH);
  if (s.empty) return;
  for (int y = s.y_lo; y <= s.y_hi; ++y) {
    int x0, x1;
    if (!model::row_span(s, y, &x0, &x1)) continue;
    for (int x = x0; x <= x1; ++x) {
      ASSERT_TRUE(x >= 0 && x < kW && y >= 0 && y < kH) << "write outside the framebuffer";
      ++counts[static_cast<size_t>(y * kW + x)];
    }
  }
}

// Grid mesh: vertices on a lattice, jittered on the 1/256 grid, some exactly on pixel centres and
// edges; every quad split along a random diagonal, random winding. The union is the rectangle
// spanned by the lattice, so every pixel centre strictly inside it is covered exactly once.
TEST(FillRule, JitteredGridMeshCoversEveryPixelOnce) {
  for (uint32_t seed = 1; seed <= 20; ++seed) {
    uint32_t s = seed * 2654435761u;
    auto rnd = [&]() {
      s = s * 1664525u + 1013904223u;
      return s >> 8;
    };
    constexpr int kN = 9;
    double vx[kN][kN], vy[kN][kN];
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        const bool border_x = i == 0 || i == kN - 1, border_y = j == 0 || j == kN - 1;
        // Interior vertices land on pixel centres, pixel edges or anywhere on the 1/256 grid.
        const int mode = static_cast<int>(rnd() % 3);
        double jx = mode == 0 ? 0.5 : (mode == 1 ? 0.0 : static_cast<double>(rnd() % 256) / 256.0);
        double jy = mode == 0 ? 0.5 : (mode == 1 ? 0.0 : static_cast<double>(rnd() % 256) / 256.0);
        vx[j][i] = 4 + i * 6 + (border_x ? 0.0 : jx - 0.5 + static_cast<double>(rnd() % 3) - 1.0);
        vy[j][i] = 3 + j * 5 + (border_y ? 0.0 : jy - 0.5 + static_cast<double>(rnd() % 3) - 1.0);
      }
    std::vector<int> counts(kW * kH, 0);
    for (int j = 0; j + 1 < kN; ++j)
      for (int i = 0; i + 1 < kN; ++i) {
        const double ax = vx[j][i], ay = vy[j][i], bx = vx[j][i + 1], by = vy[j][i + 1];
        const double cx = vx[j + 1][i + 1], cy = vy[j + 1][i + 1], dx = vx[j + 1][i], dy = vy[j + 1][i];
        const bool flip = rnd() & 1, wind = rnd() & 1;
        auto tri = [&](double x0, double y0, double x1, double y1, double x2, double y2) {
          if (wind) cover(counts, encode(x0, y0, x1, y1, x2, y2));
          else cover(counts, encode(x0, y0, x2, y2, x1, y1));
        };
        if (flip) {
          tri(ax, ay, bx, by, cx, cy);
          tri(ax, ay, cx, cy, dx, dy);
        } else {
          tri(ax, ay, bx, by, dx, dy);
          tri(bx, by, cx, cy, dx, dy);
        }
      }
    // The outer rectangle is [4, 52] x [3, 43]: centres x + 0.5 in it, left/top edges included.
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        const bool inside = cx >= 4 && cx < 52 && cy >= 3 && cy < 43;
        ASSERT_EQ(counts[static_cast<size_t>(y * kW + x)], inside ? 1 : 0)
            << "seed " << seed << " pixel " << x << "," << y;
      }
  }
}

TEST(FillRule, FanAroundAPixelCentreCoversOnce) {
  // Eight triangles around a vertex exactly on a pixel centre, outer vertices on pixel centres too.
  const double c[2] = {20.5, 20.5};
  const double ring[8][2] = {{10.5, 10.5}, {20.5, 8.5}, {30.5, 10.5}, {32.5, 20.5},
                             {30.5, 30.5}, {20.5, 32.5}, {10.5, 30.5}, {8.5, 20.5}};
  std::vector<int> counts(kW * kH, 0);
  for (int k = 0; k < 8; ++k) {
    const auto& a = ring[k];
    const auto& b = ring[(k + 1) % 8];
    cover(counts, encode(c[0], c[1], a[0], a[1], b[0], b[1]));
  }
  for (int v : counts) ASSERT_LE(v, 1);
  EXPECT_EQ(counts[20 * kW + 20], 1);  // the shared centre vertex, drawn once
  // Each ring vertex is either owned by exactly one triangle or by none; the interior of the
  // octagon has no gaps.
  for (int y = 12; y <= 28; ++y)
    for (int x = 12; x <= 28; ++x) EXPECT_EQ(counts[static_cast<size_t>(y * kW + x)], 1) << x << "," << y;
}

TEST(FillRule, TopAndLeftEdgesAreIncluded) {
  // Axis-aligned right triangles covering [2, 6) x [2, 6) with edges through pixel centres? No:
  // edges on pixel boundaries; centres at .5 are never on them. Shift by 0.5 to put edges through
  // centres: the rectangle [2.5, 6.5] x [2.5, 6.5] owns columns/rows 2..5 (top-left rule).
  std::vector<int> counts(kW * kH, 0);
  cover(counts, encode(2.5, 2.5, 6.5, 2.5, 6.5, 6.5));
  cover(counts, encode(2.5, 2.5, 6.5, 6.5, 2.5, 6.5));
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      EXPECT_EQ(counts[static_cast<size_t>(y * kW + x)], (x >= 2 && x <= 5 && y >= 2 && y <= 5) ? 1 : 0)
          << x << "," << y;
}

TEST(Raster, DegenerateAndOffscreenTrianglesDrawNothing) {
  std::vector<int> counts(kW * kH, 0);
  cover(counts, encode(1, 1, 10, 10, 20, 20));          // collinear
  cover(counts, encode(5, 5, 5, 5, 9, 9));              // two equal vertices
  cover(counts, encode(-50, -50, -10, -50, -30, -10));  // off screen
  cover(counts, encode(100, 10, 200, 10, 150, 40));     // right of the screen
  cover(counts, encode(3.1, 3.1, 3.4, 3.1, 3.1, 3.4));  // no pixel centre inside
  for (int v : counts) EXPECT_EQ(v, 0);
}

TEST(Raster, HugeTrianglesAreClippedToTheScreen) {
  std::vector<int> counts(kW * kH, 0);
  cover(counts, encode(-20000, -20000, 30000, -20000, -20000, 30000));
  cover(counts, encode(30000, -20000, 30000, 30000, -20000, 30000));
  for (int v : counts) EXPECT_EQ(v, 1);
}

TEST(Raster, RenderWritesEveryCoveredPixelOnceAndKeepsTheRest) {
  ScreenScene sc;
  sc.width = kW;
  sc.height = kH;
  sc.clear_color = 0x1234;
  ScreenTri t;
  t.state.textured = false;
  t.state.gouraud = false;
  t.state.depth_func = DepthFunc::Always;
  t.v[0] = {10.5, 10.5, 0.5, 1, 0, 0, 1, 0, 0, 1};
  t.v[1] = {30.5, 12.5, 0.5, 1, 0, 0, 1, 0, 0, 1};
  t.v[2] = {12.5, 40.5, 0.5, 1, 0, 0, 1, 0, 0, 1};
  sc.tris.push_back(t);
  std::swap(t.v[1], t.v[2]);  // the same triangle, other winding: drawn as well
  sc.tris.push_back(t);
  const Frame f = render_model(sc, model_config("full"));
  std::vector<int> counts(kW * kH, 0);
  cover(counts, encode(10.5, 10.5, 30.5, 12.5, 12.5, 40.5));
  uint64_t covered = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    covered += counts[i];
    EXPECT_EQ(f.color[i], counts[i] ? 0xF800 : 0x1234) << i;
  }
  EXPECT_EQ(f.counters.triangles, 2u);
  EXPECT_EQ(f.counters.fragments, 2 * covered);
  EXPECT_GT(covered, 200u);
}

}  // namespace
}  // namespace htx
