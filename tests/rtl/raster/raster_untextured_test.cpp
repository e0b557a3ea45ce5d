// The `icebreaker` raster unit built without texture mapping (Methods = 0, the Verilated model
// "icebreaker_untextured"; synth-report design raster_icebreaker_untextured_up5k): it draws every
// untextured triangle bit for bit as the model's `icebreaker` configuration does, whatever method
// its state word names, never uses the texture port, and refuses a textured triangle (ERR_STATE,
// nothing drawn) between good ones.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/scenes.hpp"
#include "htx/rtl/raster_engine.hpp"
#include "htx/rtl/raster_sim.hpp"
#include "htx_regs.h"
#include "raster_drive.hpp"

namespace htx {
namespace {

using raster_test::draw;
using raster_test::encode;
using raster_test::RtlResult;

constexpr const char* kBuild = "icebreaker_untextured";

void expect_matches_model(const ScreenScene& s, const std::string& what) {
  const ModelConfig cfg = rtl_config("icebreaker");
  const Frame m = render_model(s, cfg);
  const RtlResult r = draw(kBuild, encode(s, cfg), s.width, s.height, s.clear_color, s.clear_depth, cfg.z_bits);
  ASSERT_EQ(r.color.size(), m.color.size()) << what;
  EXPECT_EQ(raster_test::mismatch_pixels(r, m), 0u) << what;
  EXPECT_EQ(r.fragments, m.counters.fragments) << what;
  EXPECT_EQ(r.pixels, m.counters.pixels_written) << what;
  EXPECT_TRUE(r.requests.empty()) << what << ": the texture port was used";
}

TEST(RasterUntextured, CapsNamesNoMethod) {
  rtl::RasterSim sim(kBuild);
  const uint32_t caps = sim.read_reg(HTX_TEST_REG(CAPS));
  EXPECT_EQ(caps & RASTER_CAPS_METHODS_Msk, 0u);
  EXPECT_NE(caps & RASTER_CAPS_COUNTERS_Msk, 0u);
}

TEST(RasterUntextured, BuiltinScenesMatchModel) {
  for (const SceneInfo& info : builtin_scenes()) {
    for (bool gouraud : {true, false}) {
      ScreenScene s = prepare_screen_scene(make_builtin_scene(info.name), 160, 120);
      s.clear_color = 0x1234;
      s.clear_depth = 0xFFFFFFFFu;
      for (ScreenTri& t : s.tris) {
        t.state.textured = false;
        t.state.gouraud = gouraud;
      }
      expect_matches_model(s, info.name + (gouraud ? " gouraud" : " flat"));
    }
  }
}

TEST(RasterUntextured, RandomTrianglesMatchModel) {
  for (uint32_t seed = 11; seed <= 12; ++seed)  // 2,000 triangles, every method field
    expect_matches_model(raster_test::random_scene(seed, 1000, 96, 64), "seed " + std::to_string(seed));
}

// A textured triangle is consumed without drawing and raises ERR_STATE; the untextured triangles
// around it are drawn as the model draws them without it.
TEST(RasterUntextured, TexturedTriangleIsRefused) {
  const ModelConfig cfg = rtl_config("icebreaker");
  ScreenScene s = raster_test::random_scene(21, 40, 64, 48);
  std::vector<raster_test::Tri> tris = encode(s, cfg);
  ASSERT_GE(tris.size(), 20u);
  // A white triangle over the whole screen that always passes the depth test: drawn, it would
  // change every pixel.
  ScreenScene cover;
  ScreenTri big;
  const double xy[3][2] = {{-10, -10}, {200, -10}, {-10, 200}};
  for (int i = 0; i < 3; ++i) {
    big.v[i].x = xy[i][0];
    big.v[i].y = xy[i][1];
    big.v[i].z = 0.5;
    big.v[i].w = 1;
    big.v[i].r = big.v[i].g = big.v[i].b = big.v[i].a = 1;
  }
  big.state.textured = true;
  big.state.method = Method::Affine;
  big.state.depth_func = DepthFunc::Always;
  big.state.depth_write = true;
  cover.tris.push_back(big);
  const std::vector<raster_test::Tri> cover_tris = encode(cover, cfg);
  ASSERT_EQ(cover_tris.size(), 1u);
  const raster_test::Tri& textured = cover_tris[0];
  // Between two halves of the scene, and last (where nothing can draw over it).
  std::vector<raster_test::Tri> stream(tris.begin(), tris.begin() + 10);
  stream.push_back(textured);
  stream.insert(stream.end(), tris.begin() + 10, tris.end());
  stream.push_back(textured);

  rtl::RasterSim sim(kBuild);
  raster_test::clear_frame(sim, s.width, s.height, s.clear_color, s.clear_depth);
  const rtl::FifoRecords form = raster_test::fifo_form(sim, kBuild, s.width, s.height);
  std::vector<uint32_t> words;
  size_t sent = 0;
  for (const raster_test::Tri& t : stream)
    sent += form.append(&words, pack_state_word(t.state, t.state.method, t.top_level), t.rec) ? 1 : 0;
  sim.push_words(words);
  sim.wait_idle(50'000'000);
  const uint32_t status = sim.read_reg(HTX_TEST_REG(STATUS));
  EXPECT_NE(status & RASTER_STATUS_ERR_STATE_Msk, 0u);
  EXPECT_EQ(status & RASTER_STATUS_BUSY_Msk, 0u);
  EXPECT_EQ(sim.read_reg(HTX_TEST_REG(CNT_TRIANGLES)), sent);

  RtlResult r;
  raster_test::read_frame(sim, s.width, s.height, cfg.z_bits, &r);
  const Frame m = render_model(s, cfg);  // the scene without the textured triangle
  EXPECT_EQ(raster_test::mismatch_pixels(r, m), 0u);
}

}  // namespace
}  // namespace htx
