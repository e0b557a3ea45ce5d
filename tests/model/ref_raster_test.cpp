// The `ref` engine against hand-computed coverage, interpolation, LOD, tie rules and depth tests.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "htx/model/proc_textures.hpp"
#include "htx/model/ref.hpp"
#include "htx/model/texture.hpp"

namespace htx {
namespace {

ScreenVertex sv(double x, double y, double u = 0, double v = 0, double w = 1, double z = 0.5) {
  ScreenVertex p;
  p.x = x;
  p.y = y;
  p.u = u;
  p.v = v;
  p.w = w;
  p.z = z;
  return p;
}

ScreenTri tri(ScreenVertex a, ScreenVertex b, ScreenVertex c) {
  ScreenTri t;
  t.v = {a, b, c};
  t.state.depth_func = DepthFunc::Always;
  return t;
}

ScreenScene blank(int w, int h) {
  ScreenScene s;
  s.width = w;
  s.height = h;
  s.textures.push_back(gradient_texture(TexFormat::RGB565, 6));
  return s;
}

TEST(RefRaster, TopLeftRuleOnSquareWithCentresOnEveryEdge) {
  ScreenScene s = blank(8, 8);
  // Square with corners on pixel centres, split along its diagonal: every edge passes through centres.
  s.tris.push_back(tri(sv(0.5, 0.5), sv(4.5, 0.5), sv(4.5, 4.5)));
  s.tris.push_back(tri(sv(0.5, 0.5), sv(0.5, 4.5), sv(4.5, 4.5)));  // other winding on purpose
  const auto count = ref_coverage_count(s);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      // Top and left edges (row 0, column 0) are in, right and bottom (row 4, column 4) out.
      const unsigned want = (i < 4 && j < 4) ? 1 : 0;
      EXPECT_EQ(count[static_cast<size_t>(j * 8 + i)], want) << i << "," << j;
    }
}

TEST(RefRaster, HypotenuseBelongsToTheTriangleOnItsLeft) {
  ScreenScene s = blank(4, 4);
  s.tris.push_back(tri(sv(0, 0), sv(4, 0), sv(0, 4)));  // centres with i + j = 3 lie on its right edge
  auto count = ref_coverage_count(s);
  int n = 0;
  for (unsigned c : count) n += static_cast<int>(c);
  EXPECT_EQ(n, 6);  // i + j <= 2
  s.tris[0] = tri(sv(4, 0), sv(4, 4), sv(0, 4));
  count = ref_coverage_count(s);
  n = 0;
  for (unsigned c : count) n += static_cast<int>(c);
  EXPECT_EQ(n, 10);  // i + j >= 3, the hypotenuse being its left edge
}

TEST(RefRaster, FanWithArbitraryDoublesIsWatertight) {
  // Exact predicates: a fan around a non-grid centre with non-grid rim points covers every pixel
  // centre strictly inside the rim exactly once.
  ScreenScene s = blank(64, 64);
  const double cx = 31.123456789, cy = 32.987654321, r = 29.5;
  const int n = 997;
  auto rim = [&](int k) {
    const double a = 2 * 3.14159265358979 * k / n;
    return sv(cx + r * std::cos(a), cy + r * std::sin(a));
  };
  for (int k = 0; k < n; ++k) s.tris.push_back(tri(sv(cx, cy), rim(k), rim(k + 1)));
  const auto count = ref_coverage_count(s);
  int inside = 0;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const double dx = i + 0.5 - cx, dy = j + 0.5 - cy;
      const double d = std::sqrt(dx * dx + dy * dy);
      if (d < r * std::cos(3.14159265358979 / n) - 1e-9) {
        ++inside;
        EXPECT_EQ(count[static_cast<size_t>(j * 64 + i)], 1u) << i << "," << j;
      } else if (d > r + 1e-9) {
        EXPECT_EQ(count[static_cast<size_t>(j * 64 + i)], 0u) << i << "," << j;
      }
    }
  EXPECT_GT(inside, 2500);
}

TEST(RefRaster, PerspectiveCorrectUAndLodMatchClosedForm) {
  // Left edge at x = 8 with w = 1 and u = 0, apex at x = 248 with w = r and u = du: then u depends on
  // x only: u(t) = du * t / r / (1 + (1/r - 1) t), t = (x - 8) / 240.
  const double r = 7, du = 100;
  ScreenScene s = blank(256, 64);
  s.tris.push_back(tri(sv(8, 0, 0, 0, 1), sv(248, 32, du, 0, r), sv(8, 64, 0, 0, 1)));
  s.tris[0].state.filter = Filter::Trilinear;
  const Frame f = render_ref(s, {});
  int checked = 0;
  for (int i = 10; i < 240; i += 7) {
    const PixelProbe& p = f.probe[static_cast<size_t>(32 * 256 + i)];
    ASSERT_TRUE(p.covered) << i;
    const double t = (i + 0.5 - 8) / 240;
    const double den = 1 + (1 / r - 1) * t;
    EXPECT_NEAR(p.u, du * t / r / den, 1e-9);
    // du/dx = du / r / den^2 / 240; v is constant, so the LOD is log2 |du/dx|.
    EXPECT_NEAR(p.lod, std::log2(du / r / (den * den) / 240), 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 30);
}

TEST(RefRaster, LodIsLog2OfLongerDerivativeVector) {
  // Affine map u = 4x, v = 2y (w equal): |d/dx| = 4, |d/dy| = 2 -> lod = 2, trilinear level 2.
  ScreenScene s = blank(16, 16);
  s.tris.push_back(tri(sv(0, 0, 0, 0), sv(16, 0, 64, 0), sv(0, 16, 0, 32)));
  s.tris[0].state.filter = Filter::Trilinear;
  const Frame f = render_ref(s, {});
  const PixelProbe& p = f.probe[static_cast<size_t>(3 * 16 + 3)];
  ASSERT_TRUE(p.covered);
  EXPECT_DOUBLE_EQ(p.u, 14);
  EXPECT_DOUBLE_EQ(p.v, 7);
  EXPECT_NEAR(p.lod, 2, 1e-12);
  EXPECT_EQ(p.level, 2);
}

TEST(RefRaster, NearestTiesGoToTheLowerTexel) {
  // u = x - 0.5: at pixel centre i the coordinate is exactly i, a tie between texels i-1 and i.
  ScreenScene s = blank(16, 4);
  s.tris.push_back(tri(sv(0, 0, -0.5, 0.25), sv(64, 0, 63.5, 0.25), sv(0, 64, -0.5, 0.25)));
  s.tris[0].state.filter = Filter::Nearest;
  s.tris[0].state.combine = Combine::Replace;
  const Frame f = render_ref(s, {});
  const Texture& tex = s.textures[0];
  for (int i = 1; i < 16; ++i) {
    EXPECT_EQ(ref_nearest_index(f.probe[static_cast<size_t>(i)].u), i - 1);
    const Rgba8 t = fetch_texel(tex, 0, static_cast<unsigned>(i - 1), 0);
    const uint16_t want = static_cast<uint16_t>((t.r >> 3) << 11 | (t.g >> 2) << 5 | (t.b >> 3));
    EXPECT_EQ(f.color[static_cast<size_t>(i)], want) << i;
  }
  EXPECT_EQ(ref_nearest_index(2.0), 1);
  EXPECT_EQ(ref_nearest_index(2.0000001), 2);
  EXPECT_EQ(ref_nearest_index(-0.5), -1);
}

TEST(RefRaster, DepthFunctionsAndWriteEnable) {
  // A first triangle at depth 0.5 (drawn with Always), then a second at the same depth, nearer
  // (0.3) and farther (0.7), with each depth function: whether the second one's fragment passes,
  // which then leaves its colour and its depth.
  struct Case {
    DepthFunc f;
    bool wins_equal, wins_nearer, wins_farther;
  };
  const Case cases[] = {{DepthFunc::Never, false, false, false},  {DepthFunc::Less, false, true, false},
                        {DepthFunc::LEqual, true, true, false},   {DepthFunc::Equal, true, false, false},
                        {DepthFunc::Greater, false, false, true}, {DepthFunc::Always, true, true, true}};
  const auto depth_word = [](double z) { return static_cast<uint32_t>(std::nearbyint(z * 16777215)); };
  for (const Case& c : cases) {
    for (const auto& [z, wins] :
         {std::pair{0.5, c.wins_equal}, std::pair{0.3, c.wins_nearer}, std::pair{0.7, c.wins_farther}}) {
      ScreenScene s = blank(4, 4);
      ScreenTri a = tri(sv(0, 0, 0, 0, 1, 0.5), sv(8, 0, 0, 0, 1, 0.5), sv(0, 8, 0, 0, 1, 0.5));
      a.state.textured = false;
      a.state.depth_func = DepthFunc::Always;
      a.v[0].r = a.v[1].r = a.v[2].r = 0;  // cyan: 0x07FF
      ScreenTri b = a;
      b.state.depth_func = c.f;
      for (auto& v : b.v) {
        v.r = 1;  // white: 0xFFFF
        v.z = z;
      }
      s.tris = {a, b};
      const Frame fr = render_ref(s, {});
      EXPECT_EQ(fr.color[0], wins ? 0xFFFFu : 0x07FFu) << "function " << static_cast<int>(c.f) << ", z " << z;
      EXPECT_EQ(fr.depth[0], depth_word(wins ? z : 0.5)) << "function " << static_cast<int>(c.f) << ", z " << z;
    }
  }
  // Write disabled: a nearer fragment that does not write leaves the farther one's depth in place.
  ScreenScene s = blank(4, 4);
  ScreenTri far = tri(sv(0, 0, 0, 0, 1, 0.8), sv(8, 0, 0, 0, 1, 0.8), sv(0, 8, 0, 0, 1, 0.8));
  far.state.textured = false;
  far.state.depth_func = DepthFunc::Less;
  ScreenTri near = far;
  for (auto& v : near.v) v.z = 0.2;
  near.state.depth_write = false;
  s.tris = {far, near};
  const Frame fr = render_ref(s, {});
  EXPECT_EQ(fr.depth[0], static_cast<uint32_t>(std::nearbyint(0.8 * 16777215)));
}

TEST(RefRaster, WrapModesAddressTheRightTexels) {
  // u = x - 8 on a 64-texel texture, one row: pixel 3 has u = -4.5 -> texel -5.
  for (Wrap w : {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror}) {
    ScreenScene s = blank(16, 2);
    s.tris.push_back(tri(sv(0, 0, -8, 0.5), sv(64, 0, 56, 0.5), sv(0, 64, -8, 0.5)));
    s.tris[0].state.filter = Filter::Nearest;
    s.tris[0].state.combine = Combine::Replace;
    s.tris[0].state.wrap_u = w;
    const Frame f = render_ref(s, {});
    const unsigned want = w == Wrap::Repeat ? 59 : w == Wrap::Clamp ? 0 : 4;
    const Rgba8 t = fetch_texel(s.textures[0], 0, want, 0);
    EXPECT_EQ(f.color[3], static_cast<uint16_t>((t.r >> 3) << 11 | (t.g >> 2) << 5 | (t.b >> 3)))
        << static_cast<int>(w);
  }
}

TEST(RefRaster, HandlesDegenerateAndOffscreenTriangles) {
  ScreenScene s = blank(8, 8);
  s.tris.push_back(tri(sv(1, 1), sv(5, 5), sv(3, 3)));                // zero area
  s.tris.push_back(tri(sv(-50, -50), sv(-40, -50), sv(-50, -40)));    // off screen
  s.tris.push_back(tri(sv(-1e6, -1e6), sv(1e6, -1e6), sv(0, 1e6)));   // huge: covers all
  s.tris.push_back(tri(sv(NAN, 0), sv(1, 1), sv(2, 0)));              // malformed: nothing
  const Frame f = render_ref(s, {});
  EXPECT_EQ(f.counters.fragments, 64u);
}

}  // namespace
}  // namespace htx
