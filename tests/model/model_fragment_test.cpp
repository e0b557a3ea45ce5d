// Fragment stage of the model: depth functions and write enable at 16 and 24 bits, clear depth,
// Gouraud and flat colour, texture combine (replace, modulate), RGB565 output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "htx/fw/auto_select.h"
#include "htx/model/model.hpp"
#include "htx/model/perspective.hpp"
#include "htx/model/texture.hpp"

namespace htx {
namespace {

constexpr int kW = 16, kH = 12;

// Two triangles covering the whole screen at depth z with a flat colour.
void add_quad(ScreenScene& sc, double z, double r, double g, double b, DepthFunc f, bool write) {
  ScreenTri t;
  t.state.textured = false;
  t.state.gouraud = false;
  t.state.depth_func = f;
  t.state.depth_write = write;
  auto vtx = [&](double x, double y) { return ScreenVertex{x, y, z, 1, 0, 0, r, g, b, 1}; };
  t.v = {vtx(0, 0), vtx(kW, 0), vtx(0, kH)};
  sc.tris.push_back(t);
  t.v = {vtx(kW, 0), vtx(kW, kH), vtx(0, kH)};
  sc.tris.push_back(t);
}

ScreenScene base_scene() {
  ScreenScene sc;
  sc.width = kW;
  sc.height = kH;
  sc.clear_color = 0;
  add_quad(sc, 0.5, 1, 0, 0, DepthFunc::Always, true);  // red at z = 0.5
  return sc;
}

TEST(Depth, EveryFunctionAgainstEqualNearerAndFartherFragments) {
  struct Case {
    DepthFunc f;
    bool pass_nearer, pass_equal, pass_farther;
  };
  const Case cases[] = {{DepthFunc::Never, false, false, false},  {DepthFunc::Less, true, false, false},
                        {DepthFunc::LEqual, true, true, false},   {DepthFunc::Equal, false, true, false},
                        {DepthFunc::Greater, false, false, true}, {DepthFunc::Always, true, true, true}};
  for (const char* cfg : {"icebreaker", "full"})
    for (const Case& c : cases) {
      const double zs[3] = {0.25, 0.5, 0.75};
      const bool want[3] = {c.pass_nearer, c.pass_equal, c.pass_farther};
      for (int k = 0; k < 3; ++k) {
        ScreenScene sc = base_scene();
        add_quad(sc, zs[k], 0, 1, 0, c.f, true);  // green
        const Frame f = render_model(sc, model_config(cfg));
        for (uint16_t px : f.color)
          ASSERT_EQ(px, want[k] ? 0x07E0 : 0xF800) << cfg << " func " << int(c.f) << " z " << zs[k];
      }
    }
}

TEST(Depth, StoredValuesAndWriteEnable) {
  for (const char* cfg_name : {"icebreaker", "full"}) {
    const ModelConfig& cfg = model_config(cfg_name);
    const uint32_t top = (1u << cfg.z_bits) - 1;
    ScreenScene sc = base_scene();
    sc.clear_depth = 0xFFFFFFFFu;
    Frame f = render_model(sc, cfg);
    // z = 0.5 -> round(0.5 * (2^n - 1)), ties up: 2^(n-1).
    for (uint32_t d : f.depth) ASSERT_EQ(d, top / 2 + 1) << cfg_name;
    // A nearer fragment without depth write changes colour but not depth: a following EQUAL test
    // against the old depth still passes.
    add_quad(sc, 0.25, 0, 1, 0, DepthFunc::Less, false);
    add_quad(sc, 0.5, 0, 0, 1, DepthFunc::Equal, true);
    f = render_model(sc, cfg);
    for (size_t i = 0; i < f.color.size(); ++i) {
      ASSERT_EQ(f.color[i], 0x001F) << cfg_name;
      ASSERT_EQ(f.depth[i], top / 2 + 1) << cfg_name;
    }
    // Clear depth is clipped to the configured width; with no triangle it stays.
    ScreenScene empty;
    empty.width = kW;
    empty.height = kH;
    empty.clear_depth = 0xFFFFFFFFu;
    empty.clear_color = 0xABCD;
    f = render_model(empty, cfg);
    for (size_t i = 0; i < f.depth.size(); ++i) {
      ASSERT_EQ(f.depth[i], top);
      ASSERT_EQ(f.color[i], 0xABCD);
      ASSERT_FALSE(f.probe[i].covered);
    }
  }
}

TEST(Fragment, GouraudInterpolatesAndFlatTakesVertexZero) {
  ScreenScene sc;
  sc.width = kW;
  sc.height = kH;
  ScreenTri t;
  t.state.textured = false;
  t.state.depth_func = DepthFunc::Always;
  // Red grows along x from 0 at x = 0 to 1 at x = 16.
  t.v = {ScreenVertex{0, 0, 0, 1, 0, 0, 0, 0, 0, 1}, ScreenVertex{16, 0, 0, 1, 0, 0, 1, 0, 0, 1},
         ScreenVertex{0, 16, 0, 1, 0, 0, 0, 0, 0, 1}};
  t.state.gouraud = true;
  sc.tris = {t};
  Frame f = render_model(sc, model_config("full"));
  // Pixel (x, 0): red = round(255 (x + 0.5) / 16) then to 5 bits.
  for (int x = 0; x < 15; ++x) {
    const unsigned r8 = (255 * (2 * x + 1) + 16) / 32;
    EXPECT_EQ(f.color[static_cast<size_t>(x)] >> 11, quantise_channel(r8, 5)) << x;
  }
  t.state.gouraud = false;
  t.v[0].g = 1;
  sc.tris = {t};
  f = render_model(sc, model_config("full"));
  EXPECT_EQ(f.color[5], 0x07E0);  // vertex 0's colour (green) everywhere
  EXPECT_EQ(f.color[kW + 3], 0x07E0);
}

TEST(Fragment, CombineReplaceAndModulate) {
  std::vector<uint8_t> px(8 * 8 * 4);
  for (size_t i = 0; i < 64; ++i) {
    px[4 * i] = 200;
    px[4 * i + 1] = 100;
    px[4 * i + 2] = 50;
    px[4 * i + 3] = 255;
  }
  ScreenScene sc;
  sc.width = kW;
  sc.height = kH;
  sc.textures.push_back(make_texture(TexFormat::RGBA4444, 3, 3, px));  // 200 -> 12 -> 204, 100 -> 6 -> 102, 50 -> 3 -> 51
  ScreenTri t;
  t.state.depth_func = DepthFunc::Always;
  t.state.filter = Filter::Nearest;
  t.state.gouraud = false;
  const double c = 128.0 / 255.0;
  t.v = {ScreenVertex{0, 0, 0, 1, 0, 0, c, c, c, 1}, ScreenVertex{32, 0, 0, 1, 8, 0, c, c, c, 1},
         ScreenVertex{0, 32, 0, 1, 0, 8, c, c, c, 1}};
  for (Combine comb : {Combine::Replace, Combine::Modulate}) {
    t.state.combine = comb;
    sc.tris = {t};
    const Frame f = render_model(sc, model_config("icebreaker"));
    // modulate: round(204*128/255) = 102, round(102*128/255) = 51, round(51*128/255) = 26
    const unsigned r = comb == Combine::Replace ? 204 : 102, g = comb == Combine::Replace ? 102 : 51,
                   b = comb == Combine::Replace ? 51 : 26;
    const uint16_t want = static_cast<uint16_t>((quantise_channel(r, 5) << 11) | (quantise_channel(g, 6) << 5) |
                                                quantise_channel(b, 5));
    EXPECT_EQ(f.color[3 * kW + 3], want) << int(comb);
    EXPECT_TRUE(f.probe[3 * kW + 3].covered);
  }
}

TEST(Fragment, UnbuiltFeaturesAreRejectedClearly) {
  ScreenScene sc = base_scene();
  std::vector<uint8_t> px(8 * 8 * 4, 255);
  sc.textures.push_back(make_texture(TexFormat::RGBA8888, 3, 3, px));
  sc.tris[0].state.textured = true;
  sc.tris[0].state.texture = 0;
  EXPECT_THROW(render_model(sc, model_config("icebreaker")), std::invalid_argument);  // no RGBA8888
  sc.textures[0] = make_texture(TexFormat::RGB565, 3, 3, px);
  sc.tris[0].state.filter = Filter::Trilinear;
  EXPECT_THROW(render_model(sc, model_config("icebreaker")), std::invalid_argument);  // no trilinear
  EXPECT_NO_THROW(render_model(sc, model_config("full")));
  sc.tris[0].state.texture = 3;
  EXPECT_THROW(render_model(sc, model_config("full")), std::invalid_argument);
  sc.tris[0].state.texture = 0;
  sc.tris[0].state.method = Method::Subdiv;
  sc.tris[0].state.subdiv_n = 65;
  EXPECT_THROW(render_model(sc, model_config("full")), std::invalid_argument);
  EXPECT_THROW(model_config("nosuch"), std::invalid_argument);
  sc.width = 0;
  EXPECT_THROW(render_model(sc, model_config("full")), std::invalid_argument);
}

}  // namespace
}  // namespace htx

namespace htx {
namespace {

TEST(Trilinear, ProbeLevelFollowsTheLod) {
  // A receding textured quad: the LOD grows towards the top of the screen.
  std::vector<uint8_t> px(64 * 64 * 4);
  for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<uint8_t>(i * 37);
  ScreenScene sc;
  sc.width = 64;
  sc.height = 64;
  sc.textures.push_back(make_texture(TexFormat::RGB565, 6, 6, px));
  ScreenTri t;
  t.state.filter = Filter::Trilinear;
  t.state.depth_func = DepthFunc::Always;
  auto vtx = [](double x, double y, double w, double u, double v) {
    return ScreenVertex{x, y, 0.5, w, u, v, 1, 1, 1, 1};
  };
  t.v = {vtx(0, 64, 1, 0, 0), vtx(64, 64, 1, 64, 0), vtx(24, 0, 40, 0, 2048)};
  sc.tris.push_back(t);
  const Frame f = render_model(sc, model_config("full"));
  int levels_seen = 0, last = -1;
  uint64_t covered = 0;
  for (const PixelProbe& p : f.probe) {
    if (!p.covered) continue;
    ++covered;
    const int want = std::min(6, std::max(0, static_cast<int>(std::floor(p.lod))));
    ASSERT_EQ(p.level, want) << p.lod;
    if (p.level != last) ++levels_seen, last = p.level;
  }
  EXPECT_GT(covered, 1000u);
  EXPECT_GE(levels_seen, 3);
}

TEST(Auto, AffineWhenFlatAndADivisionUnderPerspective) {
  ScreenTri t;
  t.v = {ScreenVertex{0, 0, 0, 1, 0, 0}, ScreenVertex{100, 0, 0, 1, 64, 0}, ScreenVertex{0, 100, 0, 1, 0, 64}};
  EXPECT_EQ(model::auto_method(t, model_config("full")), Method::Affine);
  t.v[2].w = 4;
  EXPECT_EQ(model::auto_method(t, model_config("full")), Method::RecipNr);
  ModelConfig no_nr = model_config("full");
  no_nr.methods &= ~(1u << static_cast<unsigned>(Method::RecipNr));
  EXPECT_EQ(model::auto_method(t, no_nr), Method::RecipLut);
}

}  // namespace
}  // namespace htx

namespace htx {
namespace {

TEST(Fragment, GouraudScreenLinearOrPerspectiveCorrect) {
  ScreenScene sc;
  sc.width = 64;
  sc.height = 64;
  ScreenTri t;
  t.state.textured = false;
  t.state.depth_func = DepthFunc::Always;
  const double xs[3] = {2, 62, 2}, ys[3] = {2, 2, 62}, ws[3] = {1, 8, 3}, rs[3] = {0, 1, 0.25};
  for (int i = 0; i < 3; ++i) t.v[i] = ScreenVertex{xs[i], ys[i], 0, ws[i], 0, 0, rs[i], 0, 0, 1};
  sc.tris = {t};
  for (bool persp : {false, true}) {
    ModelConfig cfg = model_config("full");
    cfg.perspective_color = persp;
    const Frame f = render_model(sc, cfg);
    int worst = 0;
    for (int y = 3; y < 60; y += 3)
      for (int x = 3; x < 60 - y; x += 3) {
        const double px = x + 0.5, py = y + 0.5;
        const double l1 = (px - 2) / 60, l2 = (py - 2) / 60, l0 = 1 - l1 - l2;  // screen barycentrics
        double r;
        if (persp) {
          const double q0 = l0 / ws[0], q1 = l1 / ws[1], q2 = l2 / ws[2];
          r = (q0 * rs[0] + q1 * rs[1] + q2 * rs[2]) / (q0 + q1 + q2);
        } else {
          r = l0 * rs[0] + l1 * rs[1] + l2 * rs[2];
        }
        const int want = static_cast<int>(quantise_channel(static_cast<unsigned>(std::lround(r * 255)), 5));
        worst = std::max(worst, std::abs(static_cast<int>(f.color[static_cast<size_t>(y * 64 + x)] >> 11) - want));
      }
    EXPECT_LE(worst, 1) << "perspective " << persp;
  }
  // The two differ visibly on this triangle (w ratio 8).
  ModelConfig a = model_config("full"), b = model_config("full");
  a.perspective_color = false;
  b.perspective_color = true;
  EXPECT_NE(render_model(sc, a).color, render_model(sc, b).color);
}

// AUTO's costs and price are 16-bit fields of fw::AutoConfig: a larger one is refused by name
// rather than cut short.
TEST(Auto, ConfigurationRefusesACostOrPriceBeyondSixteenBits) {
  ModelConfig c = model_config("icebreaker");
  EXPECT_NO_THROW(c.validate());
  EXPECT_EQ(fw::auto_config_of(c).choice_cycles, 4500);
  c.auto_choice_cycles = 70000;
  try {
    c.validate();
    ADD_FAILURE() << "a price of 70000 CPU clocks was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("auto_"), std::string::npos) << e.what();
  }
  c = model_config("icebreaker");
  c.auto_nr_divide_cost16 = 65536;
  EXPECT_THROW(c.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace htx
