// The firmware render code (firmware/render), compiled for the host over the simulation HAL,
// renders built-in scenes through the Verilated raster subsystem (RasterSimBus: every register and
// framebuffer access a bus transaction). The vertex records it streamed, rendered by the model
// (render_model_records), give the same frame bit for bit.
#include <algorithm>
#include <gtest/gtest.h>

#include <ostream>
#include <stdexcept>
#include <string>
#include <string>
#include <vector>

#include "htx/hal/framebuffer.h"
#include "htx/hal/raster.h"
#include "htx/hal/sim/raster_sim_bus.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/scenes.hpp"
#include "htx/render/frame.h"
#include "htx/rtl/raster_engine.hpp"
#include "frame_records.hpp"
#include "hal_frame.hpp"
#include "render_scene.hpp"

namespace htx {
namespace {

struct Case {
  std::string config, scene;
  bool gouraud;
};

// Readable parameter names in test listings (instead of the object's bytes).
void PrintTo(const Case& c, std::ostream* os) { *os << c.config << " " << c.scene; }

class RenderCosim : public ::testing::TestWithParam<Case> {};

TEST_P(RenderCosim, FirmwareFrameEqualsModelFrameForTheSameRecords) {
  const Case& c = GetParam();
  constexpr int kW = 160, kH = 120;
  constexpr uint16_t kClear = 0x1234;
  Scene scene = make_builtin_scene(c.scene);
  for (Mesh& m : scene.meshes) {
    m.state.textured = false;  // the texture unit is not in the Verilated subsystem yet
    m.state.gouraud = c.gouraud;
    m.state.method = Method::Auto;
  }
  const test::RenderScene rs = test::to_render_scene(scene, kW, kH);
  const ModelConfig cfg = rtl_config(c.config);

  hal::sim::RasterSimBus bus(c.config);
  hal::sim::ScopedBus attach(bus);
  render::FrameParams frame;
  frame.viewport = {kW, kH};
  frame.format = cfg.record_format();
  frame.methods_built = cfg.methods;
  frame.cull_backfaces = rs.cull_backfaces;
  std::vector<render::Mesh> meshes;
  size_t max_vertices = 0;
  for (const auto& d : rs.meshes) {
    meshes.push_back(d.mesh);
    max_vertices = std::max(max_vertices, d.vertices.size());
  }
  std::vector<render::ClipVert> clip(max_vertices);
  std::vector<render::ScreenVert> screen(max_vertices);
  std::vector<uint8_t> codes(max_vertices);
  render::VertexCache cache{clip.data(), screen.data(), codes.data(), static_cast<uint32_t>(max_vertices)};
  render::DrawStats stats;
  render::DrawStatus mesh_status = render::kDrawOk;
  const uint64_t start = bus.cycles();
  ASSERT_EQ(render::render_frame(frame, {kClear, 0xFFFFFF}, rs.view_proj, meshes.data(),
                                 static_cast<uint32_t>(meshes.size()), &cache, 10'000'000, &stats, &mesh_status),
            render::kFrameOk)
      << "mesh status " << mesh_status;
  const uint64_t frame_cycles = bus.cycles() - start;
  EXPECT_FALSE(hal::raster_state_error());
  hal::RasterCounters counters;
  hal::raster_read_counters(&counters);

  // Read the frame back through the HAL, as firmware would.
  const Frame rtl = test::read_frame_through_hal(kW, kH, cfg.z_bits);

  // The model renders exactly the records the firmware streamed.
  const test::FrameRecords fr =
      test::frame_records(bus.fifo_words(), HTX_RASTER->CAPS, cfg, frame, rs.view_proj, meshes.data(),
                          static_cast<uint32_t>(meshes.size()), &cache);
  const std::vector<test::CapturedTriangle>& streamed = fr.tris;
  EXPECT_EQ(counters.triangles, fr.sent);
  ASSERT_EQ(streamed.size(), stats.sent);
  ASSERT_GT(stats.sent, 0u);
  RecordScene records;
  records.width = kW;
  records.height = kH;
  records.clear_color = kClear;
  records.clear_depth = 0xFFFFFF;
  for (const test::CapturedTriangle& t : streamed) records.tris.push_back({t.record, test::from_state_word(t.state_word)});
  const Frame model = render_model_records(records, cfg);

  const uint64_t drawn = static_cast<uint64_t>(
      std::count_if(model.color.begin(), model.color.end(), [](uint16_t colour) { return colour != kClear; }));
  EXPECT_GT(drawn, 1000u);
  const FrameMismatch mismatch = exact_mismatch(rtl, model);
  EXPECT_EQ(mismatch.pixels, 0u) << "first mismatch (rtl against model) at " << mismatch.first;
  EXPECT_EQ(counters.fragments, model.counters.fragments);
  // And the firmware's fixed-point geometry draws nearly what the double-precision stage does:
  // differences only along edges (vertices within 1/8 pixel, tests/unit/render_geometry_test).
  ScreenScene host = prepare_screen_scene(scene, kW, kH);
  host.clear_color = kClear;
  host.clear_depth = 0xFFFFFF;
  const Frame host_frame = render_model(host, cfg);
  uint64_t color_diff = 0;
  for (size_t i = 0; i < model.color.size(); ++i) color_diff += host_frame.color[i] != model.color[i];
  EXPECT_LT(color_diff, drawn / 50) << "pixels whose colour differs from the double-precision geometry's frame";
  EXPECT_EQ(counters.pixels, model.counters.pixels_written);
  std::printf("cosim %s %s: %u triangles sent (%u clipped, %u culled), frame %llu simulated clocks, raster busy %u\n",
              c.config.c_str(), c.scene.c_str(), stats.sent, stats.clipped, stats.culled,
              static_cast<unsigned long long>(frame_cycles), counters.busy);
}

// A write the unit answers with an error is a store fault on the SoC; over RasterSimBus it is an
// exception naming the address, not a word lost without a sign: the FIFO filled while
// CTRL.ENABLE is 0 refuses the next word.
TEST(RenderCosimBus, AWriteTheUnitRefusesIsAnError) {
  hal::sim::RasterSimBus bus("icebreaker");
  hal::sim::ScopedBus attach(bus);
  HTX_RASTER->CTRL = 0;  // disabled: the FIFO fills and is not drained
  int taken = 0;
  try {
    for (; taken < 4096; ++taken) HTX_RASTER->FIFO = 0x00310000u;
    ADD_FAILURE() << "4096 words into a disabled unit's FIFO, none refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bus error on register write"), std::string::npos) << e.what();
  }
  EXPECT_GT(taken, 0);
  EXPECT_LT(taken, 4096);
}

INSTANTIATE_TEST_SUITE_P(Scenes, RenderCosim,
                         ::testing::Values(Case{"icebreaker", "cube", true}, Case{"full", "cube", true},
                                           Case{"icebreaker", "floor", true}, Case{"full", "floor", false}),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return i.param.config + "_" + i.param.scene + (i.param.gouraud ? "_gouraud" : "_flat");
                         });

}  // namespace
}  // namespace htx
