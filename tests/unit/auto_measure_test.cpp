// AUTO's acceptance figures, measured (label `model`): on `floor` and `cube` at 320x240 in the
// `icebreaker` configuration (shared reciprocal unit, one division every 3 clocks), AUTO with a
// tolerance of 1/16 texel keeps the max texel-coordinate error against `ref` (the model engine's
// metrics) within 1/16 and takes fewer raster cycles (the model's cycle estimate) than RECIP_NR.
// The same path as `htx render SCENE --engine model --config icebreaker --method auto --tolerance 0.0625`.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "htx/fw/auto_scene.h"
#include "htx/model/config.hpp"
#include "htx/model/geometry.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/model.hpp"
#include "htx/model/ref.hpp"
#include "htx/model/scenes.hpp"

namespace htx {
namespace {

struct Measured {
  double max_error = 0;
  uint64_t cycles = 0, compared = 0;
  fw::AutoSceneSummary summary;
};

Measured measure(const std::string& scene_name, Method method, float tolerance) {
  const ModelConfig& cfg = model_config("icebreaker");
  ScreenScene screen = prepare_screen_scene(make_builtin_scene(scene_name), 320, 240);
  for (ScreenTri& t : screen.tris) t.state.method = method;
  Measured m;
  m.summary = fw::resolve_auto_methods(screen, cfg, tolerance);
  const Frame frame = render_model(screen, cfg);
  RefOptions ro;
  ro.depth_bits = cfg.z_bits;
  const Frame ref = render_ref(screen, ro);
  const Metrics met = compute_metrics(frame, ref, {"model", scene_name, "m", "scene", "icebreaker"});
  m.max_error = met.max_texel_error;
  m.compared = met.compared_pixels;
  m.cycles = frame.counters.cycles;
  return m;
}

void check_scene(const std::string& name) {
  constexpr float kTolerance = 1.0f / 16;
  const Measured nr = measure(name, Method::RecipNr, kTolerance);
  const Measured au = measure(name, Method::Auto, kTolerance);
  const fw::AutoSceneSummary& s = au.summary;
  std::printf(
      "AUTO %s icebreaker tol 1/16: max texel error %.5f (RECIP_NR %.5f), raster cycles %llu vs RECIP_NR %llu "
      "(%.1f %%); triangles affine %u subdiv %u recip_lut %u recip_nr %u divfree %u, not within %u\n",
      name.c_str(), au.max_error, nr.max_error, static_cast<unsigned long long>(au.cycles),
      static_cast<unsigned long long>(nr.cycles), 100.0 * static_cast<double>(au.cycles) / static_cast<double>(nr.cycles),
      s.per_method[0], s.per_method[1], s.per_method[2], s.per_method[3], s.per_method[4], s.not_within);
  ASSERT_GT(au.compared, 10000u) << "the scene must be textured on many pixels";
  EXPECT_EQ(s.resolved, s.per_method[0] + s.per_method[1] + s.per_method[2] + s.per_method[3] + s.per_method[4]);
  EXPECT_GT(s.resolved, 0u);
  EXPECT_LE(au.max_error, 1.0 / 16);
  EXPECT_LT(au.cycles, nr.cycles);
  // AUTO is not RECIP_NR in disguise: it picks a cheaper method for some triangles.
  EXPECT_LT(s.per_method[fw::kAutoRecipNr], s.resolved);
}

TEST(AutoMeasured, FloorWithinOneSixteenthAndFewerCyclesThanRecipNr) { check_scene("floor"); }
TEST(AutoMeasured, CubeWithinOneSixteenthAndFewerCyclesThanRecipNr) { check_scene("cube"); }

}  // namespace
}  // namespace htx
