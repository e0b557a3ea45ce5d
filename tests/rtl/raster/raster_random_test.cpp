// RTL against the model on random triangles (fixed seeds): random positions (on and off the screen,
// tiny to huge), random colours, depth, depth functions, depth write, flat or Gouraud.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "htx/model/model.hpp"
#include "htx/rtl/raster_engine.hpp"

namespace htx {
namespace {

ScreenScene random_scene(uint32_t seed, int n, int width, int height) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ScreenScene s;
  s.name = "random";
  s.width = width;
  s.height = height;
  s.clear_color = static_cast<uint16_t>(rng());
  s.clear_depth = rng() % 3 == 0 ? static_cast<uint32_t>(rng()) : 0xFFFFFFFFu;
  for (int i = 0; i < n; ++i) {
    ScreenTri t;
    // Size class: tiny (sub-pixel to a few pixels), screen-sized, or far beyond the screen.
    const int cls = static_cast<int>(rng() % 8);
    // (Mid-size and huge triangles are kept rarer than tiny ones so the test stays quick.)
    const double spread = cls < 4 ? 4.0 : (cls < 7 ? 40.0 : (rng() % 4 == 0 ? 3000.0 : 40.0));
    const double cx = unit(rng) * (width + 40) - 20, cy = unit(rng) * (height + 40) - 20;
    for (ScreenVertex& v : t.v) {
      v.x = cx + (unit(rng) - 0.5) * spread;
      v.y = cy + (unit(rng) - 0.5) * spread;
      v.z = unit(rng) * 1.2 - 0.1;  // clamped to [0, 1] by the encoder
      v.w = 0.5 + unit(rng) * 4;
      v.r = unit(rng);
      v.g = unit(rng);
      v.b = unit(rng);
      v.a = unit(rng);
    }
    if (rng() % 16 == 0) t.v[2] = t.v[1];  // zero area
    t.state.textured = false;
    t.state.gouraud = rng() % 4 != 0;
    t.state.depth_func = static_cast<DepthFunc>(rng() % 6);
    t.state.depth_write = rng() % 4 != 0;
    t.state.method = static_cast<Method>(rng() % 5);  // AFFINE, SUBDIV, RECIP_LUT, RECIP_NR, DIVFREE
    s.tris.push_back(t);
  }
  return s;
}

class RasterRandom : public ::testing::TestWithParam<std::string> {};

TEST_P(RasterRandom, FiveThousandTrianglesPerConfigMatchModel) {
  const ModelConfig cfg = rtl_config(GetParam());
  uint64_t total = 0;
  for (uint32_t seed = 1; seed <= 5; ++seed) {  // 5,000 per configuration, 10,000 in all
    const ScreenScene scene = random_scene(seed, 1000, 96, 64);
    const Frame model = render_model(scene, cfg);
    RtlStats stats;
    const Frame rtl = render_rtl(scene, cfg, &stats);
    ASSERT_EQ(frame_mismatch_pixels(rtl, model), 0u) << "seed " << seed;
    ASSERT_EQ(stats.covered_pixels, model.counters.fragments) << "seed " << seed;
    ASSERT_EQ(stats.pixels_written, model.counters.pixels_written) << "seed " << seed;
    ASSERT_EQ(stats.divfree_steps, model.counters.divfree_steps_total) << "seed " << seed;
    total += stats.triangles;
  }
  EXPECT_GE(total, 4500u);  // a few are rejected by the encoder (out of range) and never sent
}

INSTANTIATE_TEST_SUITE_P(Configs, RasterRandom, ::testing::Values("full", "icebreaker"));

}  // namespace
}  // namespace htx
