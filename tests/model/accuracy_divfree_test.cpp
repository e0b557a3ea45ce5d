// DIVFREE (nearest): the same texel as ref's nearest sampling on at least 99.9 % of the pixels both
// cover, on every built-in scene, its iteration cap bounds the steps of every pixel, and no pixel,
// capped or not, is further from ref than half a texel plus the RECIP_NR error budget.
// `wsweep:r=1` has an exactly integer u at every ninth pixel centre (u = (x - 16) * 8/9): exact ties
// must go to the lower texel, as in nearest sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "htx/model/config.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/model.hpp"
#include "htx/model/ref.hpp"
#include "model_test_support.hpp"

namespace htx {
namespace {

bool same_texel(const PixelProbe& e, const PixelProbe& r) {
  if (e.level != r.level) return false;
  const double k = std::ldexp(1.0, -r.level);
  return ref_nearest_index(e.u * k) == ref_nearest_index(r.u * k) &&
         ref_nearest_index(e.v * k) == ref_nearest_index(r.v * k);
}

class AccuracyDivFree : public ::testing::TestWithParam<std::string> {};

TEST_P(AccuracyDivFree, SameTexelAsRefAndCapBoundsSteps) {
  const ModelConfig& cfg = model_config("full");
  const ScreenScene s = test::screen_with(GetParam(), Method::DivFree, Filter::Nearest);
  const Frame ref = render_ref(s, {});
  const Frame model = render_model(s, cfg);
  uint64_t both = 0, same = 0;
  for (size_t i = 0; i < ref.probe.size(); ++i) {
    if (!(model.probe[i].covered && ref.probe[i].covered)) continue;
    ++both;
    same += same_texel(model.probe[i], ref.probe[i]);
    // Each axis takes at most `divfree_cap` grid steps per pixel.
    EXPECT_LE(model.probe[i].divfree_steps, 2 * cfg.divfree_cap) << "pixel " << i;
  }
  ASSERT_GT(both, 100u);
  const double share = static_cast<double>(same) / static_cast<double>(both);
  std::printf("%s: same texel on %.5f %% of %llu pixels; steps max %llu mean %.3f, cap hits %llu\n", GetParam().c_str(),
              100 * share, static_cast<unsigned long long>(both),
              static_cast<unsigned long long>(model.counters.divfree_steps_max),
              model.counters.divfree_pixels ? static_cast<double>(model.counters.divfree_steps_total) /
                                                  static_cast<double>(model.counters.divfree_pixels)
                                            : 0.0,
              static_cast<unsigned long long>(model.counters.divfree_cap_hits));
  EXPECT_GE(share, 0.999);
  EXPECT_GT(model.counters.divfree_pixels, 0u);
  EXPECT_LE(model.counters.divfree_steps_max, 2u * cfg.divfree_cap);
}

// Where the method breaks down (the cap stops the walk) the pixel takes the RECIP_NR divider's value,
// so no pixel is ever further from ref than half a texel (the cell centre DIVFREE outputs) plus the
// RECIP_NR error budget of 1/256 texel, in either configuration: no wild texels.
TEST_P(AccuracyDivFree, NoWildTexelsInEitherConfiguration) {
  const ScreenScene s = test::screen_with(GetParam(), Method::DivFree, Filter::Nearest);
  const Frame ref = render_ref(s, {});
  for (const char* cfg_name : {"full", "icebreaker"}) {
    const Frame model = render_model(s, model_config(cfg_name));
    double worst = 0;
    uint64_t both = 0;
    for (size_t i = 0; i < ref.probe.size(); ++i) {
      if (!(model.probe[i].covered && ref.probe[i].covered)) continue;
      ++both;
      worst = std::max(worst, texel_error(model.probe[i], ref.probe[i]));
    }
    std::printf("%s %s: max texel error %.5f, cap hits %llu\n", GetParam().c_str(), cfg_name, worst,
                static_cast<unsigned long long>(model.counters.divfree_cap_hits));
    ASSERT_GT(both, 100u) << cfg_name;
    EXPECT_LE(worst, 0.5 + 1.0 / 256) << cfg_name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, AccuracyDivFree, ::testing::ValuesIn(test::accuracy_scene_specs()),
                         [](const auto& param_info) {
                           std::string n = param_info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
}  // namespace htx
