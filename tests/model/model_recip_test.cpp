// The shared reciprocal unit: DasSarma-Matula table bound (exhaustive), Newton-Raphson precision.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "htx/model/recip.hpp"

namespace htx::model {
namespace {

// Largest 2 * |Y * a - 2^(2k+g+1)| over all table entries and both ends of their intervals, in units
// where the DasSarma-Matula bound 2^-(k+1) (1 + 2^-(g+1)) is (2^(g+1) + 1) * 2^k.
bool table_meets_bound(unsigned k, unsigned g, uint32_t (*entry)(unsigned, unsigned, uint32_t), double* worst) {
  const int64_t one = int64_t{1} << (2 * k + g + 1);
  const int64_t bound = ((int64_t{1} << (g + 1)) + 1) << k;
  bool ok = true;
  *worst = 0;
  for (uint32_t i = 0; i < (1u << k); ++i) {
    const int64_t y = entry(k, g, i);
    for (int64_t a : {(int64_t{1} << k) + i, (int64_t{1} << k) + i + 1}) {
      const int64_t err2 = 2 * std::llabs(y * a - one);
      if (err2 > bound) ok = false;
      *worst = std::max(*worst, static_cast<double>(err2) / static_cast<double>(bound));
    }
  }
  return ok;
}

TEST(RecipTable, DasSarmaMatulaBoundHoldsOnEveryIntervalEnd) {
  for (unsigned k = 6; k <= 12; ++k)
    for (unsigned g = 0; g <= 3; ++g) {
      double worst = 0;
      EXPECT_TRUE(table_meets_bound(k, g, recip_table_entry, &worst)) << "k=" << k << " g=" << g;
      // The bound is tight: the worst interval end comes within 10 % of it.
      EXPECT_GT(worst, 0.9) << "k=" << k << " g=" << g;
    }
}

// A plausible but wrong table (reciprocal of the interval's left end, truncated) must fail the
// same check, so the check can catch a broken table.
uint32_t left_end_truncated(unsigned k, unsigned g, uint32_t i) {
  return static_cast<uint32_t>((uint64_t{1} << (2 * k + g + 1)) / ((uint64_t{1} << k) + i));
}

TEST(RecipTable, CheckRejectsANonMidpointTable) {
  double worst = 0;
  EXPECT_FALSE(table_meets_bound(8, 2, left_end_truncated, &worst));
}

TEST(RecipTable, DasSarmaMatulaBoundHoldsForEveryMantissa) {
  // Every 20-bit mantissa through the unit with no Newton step: |r m - 1| <= bound.
  constexpr unsigned kW = 20;
  for (unsigned k = 6; k <= 12; ++k)
    for (unsigned g = 0; g <= 3; ++g) {
      const RecipParams p{k, g, kW, 0};
      const double bound = std::ldexp(1.0 + std::ldexp(1.0, -static_cast<int>(g + 1)), -static_cast<int>(k + 1));
      double worst = 0;
      for (uint64_t m = uint64_t{1} << (kW - 1); m < (uint64_t{1} << kW); ++m) {
        const double r = std::ldexp(static_cast<double>(recip_mantissa(p, m)), -static_cast<int>(kW));
        const double mm = std::ldexp(static_cast<double>(m), -static_cast<int>(kW - 1));
        worst = std::max(worst, std::fabs(r * mm - 1.0));
      }
      EXPECT_LE(worst, bound) << "k=" << k << " g=" << g;
    }
}

// Correct bits -log2(max |r m - 1|) over a dense set of mantissas (every 2^-18 of [1, 2)).
double precision_bits(const RecipParams& p) {
  double worst = 0;
  const unsigned w = p.width;
  for (uint64_t m18 = uint64_t{1} << 18; m18 < (uint64_t{1} << 19); ++m18) {
    const uint64_t m = (m18 << (w - 19)) | (m18 & 0x7F);  // low bits vary too
    const double r = std::ldexp(static_cast<double>(recip_mantissa(p, m)), -static_cast<int>(w));
    const double mm = std::ldexp(static_cast<double>(m), -static_cast<int>(w - 1));
    worst = std::max(worst, std::fabs(r * mm - 1.0));
  }
  return -std::log2(worst);
}

TEST(RecipNewton, PrecisionDoublesPerStep) {
  // Reference 000 / DasSarma-Matula: k = 8, g = 2 about 8.9 bits, about 17.8 after one step;
  // k = 10, g = 2 about 21.7 after one step.
  const double t8 = precision_bits({8, 2, 32, 0});
  const double n8 = precision_bits({8, 2, 32, 1});
  const double n10 = precision_bits({10, 2, 32, 1});
  const double nn10 = precision_bits({10, 2, 32, 2});
  std::printf("precision bits: k8g2 table %.2f, +1 NR %.2f; k10g2 +1 NR %.2f, +2 NR %.2f\n", t8, n8, n10, nn10);
  EXPECT_NEAR(t8, 8.9, 0.1);
  EXPECT_NEAR(n8, 17.7, 0.25);
  EXPECT_NEAR(n10, 21.7, 0.25);
  EXPECT_GT(nn10, 29.0);  // two steps: limited by the 32-bit datapath
  // The icebreaker datapath (W = 24) still delivers the one-step figure.
  EXPECT_NEAR(precision_bits({8, 2, 24, 1}), 17.7, 0.3);
}

TEST(RecipUnit, ReciprocalOfIntegersCarriesTheExponent) {
  const RecipParams p{10, 2, 32, 2};
  uint64_t x = 1;
  for (int i = 0; i < 2000; ++i) {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    const u128 v = (static_cast<u128>(x) << (i % 40)) | 1;
    const Reciprocal r = reciprocal(p, v);
    const double got = std::ldexp(static_cast<double>(r.value), -r.shift);
    const double want = 1.0 / static_cast<double>(v);
    EXPECT_NEAR(got / want, 1.0, std::ldexp(1.0, -28)) << i;
  }
  EXPECT_THROW(reciprocal(p, 0), std::logic_error);
}

}  // namespace
}  // namespace htx::model
