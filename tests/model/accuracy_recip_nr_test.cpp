// `full` with RECIP_NR: max texel-coordinate error <= 1/256 texel against `ref` on every built-in
// scene, including depth ratio 1000 and |u| up to 2^14; and the model draws exactly ref's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "htx/model/config.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/model.hpp"
#include "htx/model/ref.hpp"
#include "model_test_support.hpp"

namespace htx {
namespace {

class AccuracyRecipNr : public ::testing::TestWithParam<std::string> {};

TEST_P(AccuracyRecipNr, FullConfigWithinOne256thTexel) {
  for (Filter filter : {Filter::Bilinear, Filter::Trilinear}) {
    const ScreenScene s = test::screen_with(GetParam(), Method::RecipNr, filter);
    const Frame ref = render_ref(s, {});
    const Frame model = render_model(s, model_config("full"));
    const Metrics m = compute_metrics(model, ref, {"model", GetParam(), "recip_nr", "", "full"});
    EXPECT_GT(m.compared_pixels, 100u);
    EXPECT_LE(m.max_texel_error, 1.0 / 256) << "p99.9 " << m.p999_texel_error << ", rms " << m.rms_texel_error
                                            << " (filter " << static_cast<int>(filter) << ")";
    EXPECT_EQ(m.coverage_diff_pixels, 0u);
    EXPECT_EQ(m.surface_diff_pixels, 0u);  // every pixel shows ref's mesh (24-bit depth)
  }
}

// A pixel where the two frames show different meshes is not a texel error: on `bigtri` at
// 160 x 120, `icebreaker`'s 16-bit depth puts the far plane's triangle in front of the ground's
// along the horizon's row, where ref shows the ground, and their coordinates there differ by some
// 4,500 texels. The metrics count such pixels apart (surface_diff_pixels) and the error of the
// rest stays RECIP_NR's (0.0026 texel; 4,518.8 when the metrics compared every pixel).
TEST(AccuracyRecipNrSurface, AnotherMeshShownIsCountedApartNotAsAnError) {
  const ScreenScene s = test::screen_with("bigtri", Method::RecipNr, Filter::Bilinear, 160, 120);
  const Frame ref = render_ref(s, {.depth_bits = model_config("icebreaker").z_bits});
  const Frame model = render_model(s, model_config("icebreaker"));
  const Metrics m = compute_metrics(model, ref, {"model", "bigtri", "recip_nr", "", "icebreaker"});
  EXPECT_EQ(m.surface_diff_pixels, 160u);  // one row
  EXPECT_GT(m.compared_pixels, 18000u);
  EXPECT_LE(m.max_texel_error, 1.0 / 256);
  size_t meshes_seen = 0;
  for (int mesh = 0; mesh < 8; ++mesh)
    meshes_seen += std::any_of(ref.probe.begin(), ref.probe.end(), [&](const PixelProbe& p) { return p.mesh == mesh; });
  EXPECT_GE(meshes_seen, 2u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, AccuracyRecipNr, ::testing::ValuesIn(test::accuracy_scene_specs()),
                         [](const auto& param_info) {
                           std::string n = param_info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
}  // namespace htx
