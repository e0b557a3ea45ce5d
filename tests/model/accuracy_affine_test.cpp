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

// The largest |u| error over the pixels both engines cover, and how many pixels that was, against
// how many ref covers.
struct UError {
  double worst = 0;
  size_t compared = 0, ref_covered = 0;
};

UError max_u_error(const Frame& engine, const Frame& ref) {
  UError e;
  for (size_t i = 0; i < ref.probe.size(); ++i) {
    e.ref_covered += ref.probe[i].covered;
    if (engine.probe[i].covered && ref.probe[i].covered) {
      e.worst = std::max(e.worst, std::fabs(engine.probe[i].u - ref.probe[i].u));
      ++e.compared;
    }
  }
  return e;
}

// The error is taken over the whole triangle: `wsweep`'s spans 0.9 of the screen's width (left edge
// to apex) and 0.9 of its height (the left edge), so ref covers 0.405 of the screen's pixels (to
// within the edge pixels), and the model covers what ref covers (but for a few edge pixels).
void expect_compared_enough(const UError& e, const Frame& ref) {
  const double area = 0.5 * 0.9 * 0.9 * static_cast<double>(ref.probe.size());
  EXPECT_NEAR(static_cast<double>(e.ref_covered), area, 0.01 * area) << "ref covers " << e.ref_covered << " pixels";
  EXPECT_GE(e.compared, e.ref_covered - e.ref_covered / 100) << e.compared << " of " << e.ref_covered << " compared";
}

class AccuracyAffine : public ::testing::TestWithParam<double> {};

TEST_P(AccuracyAffine, WsweepErrorMatchesBound) {
  const double r = GetParam(), du = 256;
  const ScreenScene s =
      test::screen_with("wsweep:r=" + std::to_string(r) + ",du=256", Method::Affine, Filter::Nearest);
  const Frame ref = render_ref(s, {});
  const Frame model = render_model(s, model_config("full"));
  const double bound = du * (std::sqrt(r) - 1) / (std::sqrt(r) + 1);
  const UError e = max_u_error(model, ref);
  const double err = e.worst;
  std::printf("r = %g: affine max error %.4f texels, bound %.4f (ratio %.5f) over %zu pixels (ref covers %zu of %zu)\n", r,
              err, bound, err / bound, e.compared, e.ref_covered, ref.probe.size());
  expect_compared_enough(e, ref);
  EXPECT_NEAR(err / bound, 1.0, 0.02);
}

INSTANTIATE_TEST_SUITE_P(DepthRatios, AccuracyAffine, ::testing::Values(2.0, 10.0, 100.0));

TEST(AccuracyAffineFlat, NoDepthRatioNoError) {
  // r = 1: affine is exact up to the model's arithmetic.
  const ScreenScene s = test::screen_with("wsweep:r=1", Method::Affine, Filter::Nearest);
  const Frame ref = render_ref(s, {});
  const UError e = max_u_error(render_model(s, model_config("full")), ref);
  std::printf("r = 1: affine max error %.6f texels over %zu pixels (ref covers %zu of %zu)\n", e.worst, e.compared,
              e.ref_covered, ref.probe.size());
  expect_compared_enough(e, ref);
  EXPECT_LT(e.worst, 1.0 / 256);
}

}  // namespace
}  // namespace htx
