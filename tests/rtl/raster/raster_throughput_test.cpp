// Measured throughput of the perspective methods (docs/raster.md, "Measured"): covered pixels per
// busy clock on bigtri, textured (every fragment needs its texel coordinates), per method and
// configuration; setup clocks per tiny triangle per method. `full` must keep at least 0.9 pixels
// per clock with every method (its divider is pipelined; DIVFREE walks up to one grid step per axis
// in a pixel's first clock, one more per further clock). DIVFREE filters nearest (level 0).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/names.hpp"
#include "htx/model/scenes.hpp"
#include "raster_drive.hpp"

namespace htx {
namespace {

using raster_test::Tri;

const Method kBuilt[] = {Method::Affine, Method::Subdiv, Method::RecipLut, Method::RecipNr, Method::DivFree};

TEST(RasterThroughput, BigtriPixelsPerClockPerMethod) {
  for (const char* name : {"full", "icebreaker"}) {
    const ModelConfig& cfg = model_config(name);
    // icebreaker divides slowly: a quarter of the pixels is enough for its figure.
    const bool ice = name == std::string("icebreaker");
    ScreenScene s = prepare_screen_scene(make_builtin_scene("bigtri"), ice ? 80 : 160, ice ? 60 : 120);
    for (Method m : kBuilt) {
      for (ScreenTri& t : s.tris) {
        t.state.textured = true;
        t.state.gouraud = true;
        t.state.method = m;
        t.state.subdiv_n = 8;
        t.state.filter = Filter::Nearest;  // level 0 for every method (DIVFREE: whole texels)
      }
      const raster_test::RtlResult r =
          raster_test::draw(name, raster_test::encode(s, cfg), s.width, s.height, 0, 0xFFFFFFFFu, cfg.z_bits);
      ASSERT_GT(r.fragments, ice ? 2000u : 10000u);
      const double ppc = static_cast<double>(r.fragments) / static_cast<double>(r.busy);
      std::printf("bigtri %dx%d %s %s: %llu fragments, %llu busy clocks, %.3f px/clk\n", s.width, s.height, name,
                  method_name(m, 8).c_str(), static_cast<unsigned long long>(r.fragments),
                  static_cast<unsigned long long>(r.busy), ppc);
      if (name != std::string("icebreaker")) {
        EXPECT_GE(ppc, 0.9) << name << " " << method_name(m, 8);
      }
    }
  }
}

TEST(RasterThroughput, SetupClocksPerTinyTrianglePerMethod) {
  for (const char* name : {"full", "icebreaker"}) {
    const ModelConfig& cfg = model_config(name);
    for (Method m : kBuilt) {
      ScreenScene s;
      s.width = 64;
      s.height = 48;
      for (int i = 0; i < 200; ++i) {
        ScreenTri t;
        const double x = 2 + (i % 30) * 2, y = 2 + (i / 30) * 2;
        const double xs[3] = {x, x + 1.6, x + 0.3}, ys[3] = {y, y + 0.4, y + 1.7};
        for (int k = 0; k < 3; ++k) {
          t.v[k].x = xs[k];
          t.v[k].y = ys[k];
          t.v[k].w = 1.0 + 0.1 * k;
          t.v[k].u = 3.0 * k;
          t.v[k].v = 2.0 * k;
        }
        t.state.textured = true;
        t.state.method = m;
        t.state.subdiv_n = 8;
        t.state.filter = Filter::Nearest;
        s.tris.push_back(t);
      }
      const raster_test::RtlResult r =
          raster_test::draw(name, raster_test::encode(s, cfg), s.width, s.height, 0, 0xFFFFFFFFu, cfg.z_bits);
      ASSERT_EQ(r.triangles, 200u);
      const double per = static_cast<double>(r.setup_busy) / 200.0;
      std::printf("setup %s %s: %.1f clocks per tiny triangle\n", name, method_name(m, 8).c_str(), per);
      if (name == std::string("full") && m != Method::Affine) {
        EXPECT_LE(per, 24.0);
      }
    }
  }
}

}  // namespace
}  // namespace htx
