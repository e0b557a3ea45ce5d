// `full` with RECIP_NR: max texel-coordinate error <= 1/256 texel against `ref` on every built-in
// scene, including depth ratio 1000 and |u| up to 2^14; and the model draws exactly ref's pixels.
#include <gtest/gtest.h>

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
  }
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
