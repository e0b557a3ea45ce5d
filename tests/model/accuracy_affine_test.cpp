// AFFINE on `wsweep`: over a span covering du texels with depth ratio r, affine interpolation errs by
// at most du*(sqrt(r)-1)/(sqrt(r)+1) texels, and `wsweep` is built to reach that bound (1/w and u/w
// depend on screen x only, the whole span is on screen). The model's AFFINE error against ref must
// match the bound within 2 % at r = 2, 10, 100.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "htx/model/config.hpp"
#include "htx/model/model.hpp"
#include "htx/model/ref.hpp"
#include "model_test_support.hpp"

namespace htx {
namespace {

double max_u_error(const Frame& engine, const Frame& ref) {
  double worst = 0;
  for (size_t i = 0; i < ref.probe.size(); ++i)
    if (engine.probe[i].covered && ref.probe[i].covered)
      worst = std::max(worst, std::fabs(engine.probe[i].u - ref.probe[i].u));
  return worst;
}

class AccuracyAffine : public ::testing::TestWithParam<double> {};

TEST_P(AccuracyAffine, WsweepErrorMatchesBound) {
  const double r = GetParam(), du = 256;
  const ScreenScene s =
      test::screen_with("wsweep:r=" + std::to_string(r) + ",du=256", Method::Affine, Filter::Nearest);
  const Frame ref = render_ref(s, {});
  const Frame model = render_model(s, model_config("full"));
  const double bound = du * (std::sqrt(r) - 1) / (std::sqrt(r) + 1);
  const double err = max_u_error(model, ref);
  std::printf("r = %g: affine max error %.4f texels, bound %.4f (ratio %.5f)\n", r, err, bound, err / bound);
  EXPECT_NEAR(err / bound, 1.0, 0.02);
}

INSTANTIATE_TEST_SUITE_P(DepthRatios, AccuracyAffine, ::testing::Values(2.0, 10.0, 100.0));

TEST(AccuracyAffineFlat, NoDepthRatioNoError) {
  // r = 1: affine is exact up to the model's arithmetic.
  const ScreenScene s = test::screen_with("wsweep:r=1", Method::Affine, Filter::Nearest);
  EXPECT_LT(max_u_error(render_model(s, model_config("full")), render_ref(s, {})), 1.0 / 256);
}

}  // namespace
}  // namespace htx
