// Perspective-correct Gouraud colour (docs/model.md §3, `full`'s perspective_color): the planes of
// c q divided by Q per pixel through the divider. The Verilated `full` top (model_config("full")
// exactly, since 2026-12-07 as the GPU's too) against render_model, framebuffer and depth bit for bit: every built-in scene with every
// built method, and random perspective triangles (fixed seeds).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/scenes.hpp"
#include "raster_drive.hpp"

namespace htx {
namespace {

using raster_test::Tri;

const Method kBuilt[] = {Method::Affine, Method::Subdiv, Method::RecipLut, Method::RecipNr};

void expect_frame(const ScreenScene& s, const std::string& what) {
  const ModelConfig& cfg = model_config("full");
  ASSERT_TRUE(cfg.perspective_color);
  const Frame model = render_model(s, cfg);
  const raster_test::RtlResult r =
      raster_test::draw("full", raster_test::encode(s, cfg), s.width, s.height, s.clear_color, s.clear_depth,
                        cfg.z_bits);
  size_t first = 0;
  const uint64_t bad = raster_test::mismatch_pixels(r, model, &first);
  EXPECT_EQ(bad, 0u) << what << ": first mismatch at pixel " << first << ": rtl colour " << r.color[first]
                     << " depth " << r.depth[first] << ", model colour " << model.color[first] << " depth "
                     << model.depth[first];
  EXPECT_EQ(r.fragments, model.counters.fragments) << what;
  EXPECT_EQ(r.pixels, model.counters.pixels_written) << what;
}

class ColorScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(ColorScenes, PerspectiveGouraudMatchesModel) {
  ScreenScene s = prepare_screen_scene(make_builtin_scene(GetParam()), 96, 72);
  s.clear_color = 0x1234;
  s.clear_depth = 0xFFFFFFFFu;
  for (size_t i = 0; i < s.tris.size(); ++i) {
    TriState& st = s.tris[i].state;
    st.textured = false;
    st.gouraud = true;
    st.method = kBuilt[i % 4];
  }
  expect_frame(s, GetParam());
}

std::vector<std::string> scene_names() {
  std::vector<std::string> n;
  for (const SceneInfo& s : builtin_scenes()) n.push_back(s.name);
  return n;
}

INSTANTIATE_TEST_SUITE_P(All, ColorScenes, ::testing::ValuesIn(scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// Random triangles with strongly varying w (perspective), random colours, depth functions and
// methods; a quarter flat.
TEST(ColorRandom, TwoThousandPerspectiveTrianglesMatchModel) {
  for (uint32_t seed = 1; seed <= 2; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ScreenScene s;
    s.width = 64;
    s.height = 48;
    s.clear_color = static_cast<uint16_t>(rng());
    s.clear_depth = 0xFFFFFFFFu;
    for (int i = 0; i < 1000; ++i) {
      ScreenTri t;
      const double spread = rng() % 4 == 0 ? 200.0 : 25.0;
      const double cx = unit(rng) * 80 - 8, cy = unit(rng) * 60 - 6;
      for (ScreenVertex& v : t.v) {
        v.x = cx + (unit(rng) - 0.5) * spread;
        v.y = cy + (unit(rng) - 0.5) * spread;
        v.z = unit(rng);
        v.w = 0.05 + unit(rng) * (rng() % 2 ? 50.0 : 1.0);
        v.r = unit(rng); v.g = unit(rng); v.b = unit(rng); v.a = unit(rng);
      }
      t.state.textured = false;
      t.state.gouraud = rng() % 4 != 0;
      t.state.depth_func = static_cast<DepthFunc>(rng() % 6);
      t.state.depth_write = rng() % 4 != 0;
      t.state.method = kBuilt[rng() % 4];
      t.state.subdiv_n = 2 + rng() % 63;
      s.tris.push_back(t);
    }
    expect_frame(s, "seed " + std::to_string(seed));
  }
}

}  // namespace
}  // namespace htx
