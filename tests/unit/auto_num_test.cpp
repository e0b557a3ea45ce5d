// AutoNum (firmware/lib htx/fw/auto_num.h), the number type of AUTO's bounds and costs, against
// double: exact conversions, every operation within a few units of 2^-29 of the exact result over
// random operands of both signs and any exponents, comparisons that agree with the values, and
// reported floats that never understate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "htx/fw/auto_num.h"

namespace {

using htx::fw::AutoNum;

double value(AutoNum a) { return std::ldexp(static_cast<double>(a.m), a.e); }

bool normalised(AutoNum a) {
  const uint32_t mag = a.m < 0 ? 0u - static_cast<uint32_t>(a.m) : static_cast<uint32_t>(a.m);
  return a.m == 0 || (mag >= (1u << 30) && mag < (1u << 31));
}

// A random normalised value: any sign, exponents over +-40 octaves.
AutoNum random_num(std::mt19937& rng) {
  std::uniform_int_distribution<int32_t> mant(1 << 30, 0x7FFFFFFF);
  std::uniform_int_distribution<int32_t> exp(-70, 10);
  const int32_t m = mant(rng);
  return {(rng() & 1) ? -m : m, exp(rng)};
}

constexpr double kRel = 0x1p-28;  // a few units of the 31-bit mantissa

TEST(AutoNum, ConversionsAreExact) {
  for (int32_t v : {0, 1, -1, 2, 3, 7, 100, -100, 65536, 0x7FFFFFFF, -0x7FFFFFFF, std::numeric_limits<int32_t>::min()}) {
    const AutoNum n = htx::fw::num_from_int(v);
    EXPECT_TRUE(normalised(n)) << v;
    EXPECT_EQ(value(n), static_cast<double>(v)) << v;
  }
  std::mt19937 rng(5);
  std::uniform_int_distribution<uint32_t> bits;
  for (int i = 0; i < 20000; ++i) {
    uint32_t b = bits(rng);
    if (((b >> 23) & 0xFF) == 0xFF) continue;  // infinities and NaNs are not inputs
    float f;
    std::memcpy(&f, &b, sizeof f);
    const AutoNum n = htx::fw::num_from_float(f);
    ASSERT_TRUE(normalised(n)) << f;
    ASSERT_EQ(value(n), static_cast<double>(f)) << f;
    // Back to float: the same value, exactly representable.
    if (std::fabs(f) >= std::numeric_limits<float>::min()) {
      ASSERT_EQ(htx::fw::num_to_float_up(n), f) << f;
    }
  }
  EXPECT_EQ(value(htx::fw::num_pow2(-17)), 0x1p-17);
  EXPECT_EQ(value(htx::fw::num_scale(htx::fw::num_from_int(3), 5)), 96.0);
}

TEST(AutoNum, ReportedFloatIsTheSmallestNotBelow) {
  std::mt19937 rng(6);
  for (int i = 0; i < 20000; ++i) {
    const AutoNum n = random_num(rng);
    const double v = value(n);
    const float f = htx::fw::num_to_float_up(n);
    ASSERT_GE(static_cast<double>(f), v);
    ASSERT_LT(static_cast<double>(std::nextafter(f, -INFINITY)), v);
  }
  EXPECT_EQ(htx::fw::num_to_float_up(AutoNum{}), 0.0f);
  EXPECT_EQ(htx::fw::num_to_float_up(AutoNum{1 << 30, 200}), INFINITY);
}

TEST(AutoNum, ArithmeticWithinAFewUnitsOfTheExactResult) {
  std::mt19937 rng(7);
  for (int i = 0; i < 50000; ++i) {
    const AutoNum a = random_num(rng), b = random_num(rng);
    const double x = value(a), y = value(b);
    const AutoNum sum = a + b, diff = a - b, prod = a * b, quot = a / b;
    ASSERT_TRUE(normalised(sum) && normalised(diff) && normalised(prod) && normalised(quot));
    // A sum is off by less than a unit of its larger operand (cancellation keeps that absolute error).
    const double scale = std::max(std::fabs(x), std::fabs(y));
    ASSERT_NEAR(value(sum), x + y, scale * kRel) << x << " + " << y;
    ASSERT_NEAR(value(diff), x - y, scale * kRel) << x << " - " << y;
    ASSERT_NEAR(value(prod), x * y, std::fabs(x * y) * kRel) << x << " * " << y;
    ASSERT_NEAR(value(quot), x / y, std::fabs(x / y) * kRel) << x << " / " << y;
    // Comparisons agree with the values.
    ASSERT_EQ(a < b, x < y);
    ASSERT_EQ(a <= b, x <= y);
    ASSERT_EQ(a == b, x == y);
    ASSERT_EQ(htx::fw::num_min(a, b) == (x < y ? a : b), true);
    ASSERT_EQ(value(htx::fw::num_abs(a)), std::fabs(x));
  }
  // Equal magnitudes cancel to zero; zero is neutral; dividing by zero gives a huge value of the
  // dividend's sign instead of a trap.
  const AutoNum a = htx::fw::num_from_int(-12345);
  EXPECT_EQ((a - a).m, 0);
  EXPECT_EQ(value(a + AutoNum{}), -12345.0);
  EXPECT_EQ(value(a * AutoNum{}), 0.0);
  EXPECT_EQ(value(AutoNum{} / a), 0.0);
  const AutoNum inf = a / AutoNum{};
  EXPECT_LT(inf.m, 0);
  EXPECT_GT(inf.e, 1 << 19);
  EXPECT_TRUE(htx::fw::num_from_int(0) == AutoNum{});
  EXPECT_TRUE(htx::fw::num_from_int(1) > AutoNum{});
  EXPECT_TRUE(htx::fw::num_from_int(-1) < AutoNum{});
}

// Every ordering operator against the values on a set with zeros, equal values, equal exponents
// of either sign and exponents far apart, every pair (the operators take branches by sign, zero and
// exponent).
TEST(AutoNum, ComparisonsAgreeWithTheValuesOnEveryPair) {
  std::vector<AutoNum> nums = {AutoNum{}};
  for (int32_t m : {1 << 30, (1 << 30) + 1, 0x5FFFFFFF, 0x7FFFFFFF})
    for (int32_t e : {-100, -31, -30, -1, 0, 1, 30, 100})
      for (int sign : {1, -1}) nums.push_back({sign * m, e});
  for (const AutoNum& a : nums)
    for (const AutoNum& b : nums) {
      const double x = value(a), y = value(b);
      ASSERT_EQ(a < b, x < y) << a.m << "e" << a.e << " " << b.m << "e" << b.e;
      ASSERT_EQ(a > b, x > y);
      ASSERT_EQ(a <= b, x <= y);
      ASSERT_EQ(a >= b, x >= y);
      ASSERT_EQ(a == b, x == y);
      ASSERT_EQ(value(htx::fw::num_min(a, b)), std::min(x, y));
      ASSERT_EQ(value(htx::fw::num_max(a, b)), std::max(x, y));
    }
}

// The sum in 32-bit arithmetic is the sum the 64-bit formula gives, bit for bit: both halves
// shifted right, added, normalised (the reference below), on random pairs and every pair of the
// extreme mantissas at close exponents.
TEST(AutoNum, SumEqualsTheWideFormulaBitForBit) {
  auto reference = [](AutoNum a, AutoNum b) {
    if (a.m == 0) return b;
    if (b.m == 0) return a;
    if (a.e < b.e) std::swap(a, b);
    const int32_t d = a.e - b.e;
    if (d > 31) return a;
    const int64_t sum = int64_t{a.m >> 1} + ((b.m >> 1) >> d);
    if (sum == 0) return AutoNum{};
    int64_t mag = sum < 0 ? -sum : sum;
    int32_t e = a.e + 1;
    if (mag >= (int64_t{1} << 31)) return AutoNum{sum < 0 ? -(1 << 30) : (1 << 30), a.e + 2};
    while (mag < (int64_t{1} << 30)) mag <<= 1, --e;
    return AutoNum{static_cast<int32_t>(sum < 0 ? -mag : mag), e};
  };
  std::vector<std::pair<AutoNum, AutoNum>> pairs;
  std::mt19937 rng(19);
  std::uniform_int_distribution<int32_t> near(-3, 3);
  for (int i = 0; i < 100000; ++i) {
    AutoNum a = random_num(rng), b = random_num(rng);
    if (i % 2) b.e = a.e + near(rng);  // close exponents: cancellation
    pairs.emplace_back(a, b);
  }
  const int32_t edges[] = {1 << 30, (1 << 30) + 1, 0x7FFFFFFE, 0x7FFFFFFF};
  for (int32_t m : edges)
    for (int32_t n : edges)
      for (int32_t d : {0, 1, 2, 31, 32})
        for (int sa : {1, -1})
          for (int sb : {1, -1}) pairs.push_back({AutoNum{sa * m, 0}, AutoNum{sb * n, -d}});
  for (const auto& [a, b] : pairs) {
    const AutoNum got = a + b, want = reference(a, b);
    ASSERT_EQ(got.m, want.m) << a.m << "e" << a.e << " + " << b.m << "e" << b.e;
    ASSERT_EQ(got.e, want.e) << a.m << "e" << a.e << " + " << b.m << "e" << b.e;
  }
}

// Every pair of the extreme mantissas (+-2^30, +-(2^31 - 1) and their neighbours) at a few exponent
// distances: results normalised and within a few units (two mantissas of -(2^31 - 1) once summed to
// 2^31, outside the format, which a product then read as 0), and a power of two divides exactly.
TEST(AutoNum, ExtremeMantissasStayNormalised) {
  const int32_t edges[] = {1 << 30, (1 << 30) + 1, 0x7FFFFFFE, 0x7FFFFFFF};
  std::vector<AutoNum> nums;
  for (int32_t m : edges)
    for (int32_t e : {-40, -31, -30, 0, 1})
      for (int sign : {1, -1}) nums.push_back({sign * m, e});
  for (const AutoNum& a : nums)
    for (const AutoNum& b : nums) {
      const double x = value(a), y = value(b), scale = std::max(std::fabs(x), std::fabs(y));
      const AutoNum sum = a + b, diff = a - b, prod = a * b, quot = a / b;
      ASSERT_TRUE(normalised(sum) && normalised(diff) && normalised(prod) && normalised(quot))
          << a.m << "e" << a.e << " " << b.m << "e" << b.e;
      ASSERT_NEAR(value(sum), x + y, scale * kRel);
      ASSERT_NEAR(value(diff), x - y, scale * kRel);
      ASSERT_NEAR(value(prod), x * y, std::fabs(x * y) * kRel);
      ASSERT_NEAR(value(quot), x / y, std::fabs(x / y) * kRel);
      if (b.m == (1 << 30) || b.m == -(1 << 30)) {
        ASSERT_EQ(value(quot), x / y);
      }
    }
  const AutoNum one = htx::fw::num_from_int(1);
  EXPECT_EQ(value(one / one), 1.0);
  EXPECT_EQ(value(htx::fw::num_from_int(3) / htx::fw::num_from_int(-4)), -0.75);
}

// Quotients of nearby mantissas, where the reciprocal's first guess is worst (y' near 1/2, 3/4, 1).
TEST(AutoNum, DivisionAtTheReciprocalsEdges) {
  for (int32_t m : {1 << 30, (1 << 30) + 1, 0x5FFFFFFF, 0x60000000, 0x7FFFFFFE, 0x7FFFFFFF}) {
    const AutoNum y{m, -30};
    for (int32_t n : {1 << 30, 0x55555555, 0x7FFFFFFF}) {
      const AutoNum x{n, -30};
      ASSERT_NEAR(value(x / y), value(x) / value(y), value(x) / value(y) * kRel) << n << " / " << m;
    }
  }
}

}  // namespace
