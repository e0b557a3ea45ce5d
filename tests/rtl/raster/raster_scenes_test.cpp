// RTL against the model, bit for bit: framebuffer and depth buffer of every built-in scene rendered
// untextured (flat and Gouraud, depth functions as the scenes set them), in both configurations.
#include <gtest/gtest.h>

#include <string>

#include "htx/model/metrics.hpp"
#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/scenes.hpp"
#include "htx/rtl/raster_engine.hpp"

namespace htx {
namespace {

struct Case {
  std::string config;
  std::string scene;
  bool gouraud;
};

class RasterScenes : public ::testing::TestWithParam<Case> {};

TEST_P(RasterScenes, MatchesModelBitForBit) {
  const Case& c = GetParam();
  ScreenScene screen = prepare_screen_scene(make_builtin_scene(c.scene), 160, 120);
  screen.clear_color = 0x1234;
  screen.clear_depth = 0xFFFFFFFFu;
  for (ScreenTri& t : screen.tris) {
    t.state.textured = false;
    t.state.gouraud = c.gouraud;
  }
  // (`full`'s Gouraud colour is perspective-correct, `icebreaker`'s linear in screen space.)
  const ModelConfig cfg = rtl_config(c.config);
  const Frame model = render_model(screen, cfg);
  RtlStats stats;
  const Frame rtl = render_rtl(screen, cfg, &stats);
  ASSERT_EQ(rtl.color.size(), model.color.size());
  const FrameMismatch mismatch = exact_mismatch(rtl, model);
  EXPECT_EQ(mismatch.pixels, 0u) << "first mismatch (rtl against model) at " << mismatch.first;
  EXPECT_EQ(stats.covered_pixels, model.counters.fragments);
  EXPECT_EQ(stats.pixels_written, model.counters.pixels_written);
  EXPECT_EQ(stats.triangles, stats.triangles_sent);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const char* cfg : {"full", "icebreaker"})
    for (const SceneInfo& s : builtin_scenes())
      for (bool g : {true, false}) cases.push_back({cfg, s.name, g});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(All, RasterScenes, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return i.param.config + "_" + i.param.scene + (i.param.gouraud ? "_gouraud" : "_flat");
                         });

}  // namespace
}  // namespace htx
