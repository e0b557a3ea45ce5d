// htx_raster_mul Verilated alone with AWidth 38 and BWidth 26, in its iterative form (the
// `icebreaker` setup multipliers) and digit-serial with b in digits or whole (the `icebreaker`
// divider's): products bit for bit against 128-bit arithmetic, the operand extremes, the clocks per
// product, products back to back with start held, and an abort in mid-product (label `rtl`).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "Vhtx_raster_mul.h"
#include "Vhtx_raster_mul_digits.h"
#include "Vhtx_raster_mul_digits_wide_b.h"
#include "htx/model/wide.hpp"
#include "vmodel_clock.hpp"

namespace {

constexpr int kA = 38, kB = 26;  // the Verilated widths (tests/rtl/raster/CMakeLists.txt)

template <class V>
class Mul {
 public:
  Mul() {
    m_.abort_i = 0;
    m_.start_i = 0;
    m_.neg_i = 0;
    htx::raster_test::reset_model(m_);
  }
  void clock() { htx::raster_test::clock_edge(m_); }
  void operands(int64_t a, int64_t b, unsigned extra = 0) {
    m_.extra_i = static_cast<uint8_t>(extra);
    m_.a_i = static_cast<uint64_t>(a) & ((uint64_t{1} << kA) - 1);
    m_.b_i = static_cast<uint32_t>(static_cast<uint64_t>(b) & ((uint64_t{1} << kB) - 1));
  }
  // Holds start until done; returns the product and the clocks it took.
  uint64_t product(int64_t a, int64_t b, int* clocks, unsigned extra = 0) {
    operands(a, b, extra);
    m_.start_i = 1;
    int n = 0;
    do {
      clock();
      ++n;
    } while (!m_.done_o && n < 1000);
    *clocks = n;
    const uint64_t p = m_.p_o;
    m_.start_i = 0;
    clock();
    EXPECT_FALSE(m_.done_o) << "done_o is a one-clock pulse";
    return p;
  }
  V& model() { return m_; }

 private:
  V m_;
};

int64_t random_a(std::mt19937_64& rng) { return static_cast<int64_t>(rng() << (64 - kA)) >> (64 - kA); }
int64_t random_b(std::mt19937_64& rng) { return static_cast<int64_t>(rng() << (64 - kB)) >> (64 - kB); }

uint64_t expected(int64_t a, int64_t b) {
  return static_cast<uint64_t>(static_cast<htx::model::i128>(a) * b);  // the low A + B = 64 bits
}

// The operand extremes and the given edges against each other, then 3,000 random products; every
// product of the edges takes clocks_per_product clocks.
template <class V>
void check_products(int clocks_per_product, std::vector<int64_t> edges_a, std::vector<int64_t> edges_b) {
  Mul<V> mul;
  const int64_t amin = -(int64_t{1} << (kA - 1)), amax = (int64_t{1} << (kA - 1)) - 1;
  const int64_t bmin = -(int64_t{1} << (kB - 1)), bmax = (int64_t{1} << (kB - 1)) - 1;
  edges_a.insert(edges_a.begin(), {amin, amin + 1, -1, 0, 1, amax});
  edges_b.insert(edges_b.begin(), {bmin, bmin + 1, -1, 0, 1, bmax});
  int clocks = 0;
  for (int64_t a : edges_a) {
    for (int64_t b : edges_b) {
      EXPECT_EQ(mul.product(a, b, &clocks), expected(a, b)) << a << " * " << b;
      EXPECT_EQ(clocks, clocks_per_product);
    }
  }
  std::mt19937_64 rng(20261202);
  for (int i = 0; i < 3000; ++i) {
    const int64_t a = random_a(rng), b = random_b(rng);
    ASSERT_EQ(mul.product(a, b, &clocks), expected(a, b)) << a << " * " << b;
  }
}

// An abort `run` clocks into a product drops it; the next product starts at once and is the new
// one, in clocks_per_product clocks.
template <class V>
void check_abort(int run, int clocks_per_product) {
  Mul<V> mul;
  auto& m = mul.model();
  mul.operands(123456789, -4242);
  m.start_i = 1;
  for (int i = 0; i < run; ++i) mul.clock();
  m.start_i = 0;
  m.abort_i = 1;
  mul.clock();
  m.abort_i = 0;
  mul.clock();
  EXPECT_FALSE(m.done_o);
  int clocks = 0;
  EXPECT_EQ(mul.product(-987654321, 777, &clocks), expected(-987654321, 777));
  EXPECT_EQ(clocks, clocks_per_product);
}

// One bit of b per clock, then done.
TEST(RasterMul, RandomAndExtremeOperandsMatchExactProducts) { check_products<Vhtx_raster_mul>(kB + 1, {}, {}); }

// extra_i more clocks shift the product right, arithmetically: the plane unit's rounding shift.
TEST(RasterMul, ExtraClocksShiftTheProductRight) {
  Mul<Vhtx_raster_mul> mul;
  std::mt19937_64 rng(7);
  int clocks = 0;
  for (unsigned extra : {1u, 2u, 17u, 40u, 63u, 200u}) {
    for (int i = 0; i < 200; ++i) {
      const int64_t a = random_a(rng), b = random_b(rng);
      const htx::model::i128 p = static_cast<htx::model::i128>(a) * b;
      ASSERT_EQ(mul.product(a, b, &clocks, extra), static_cast<uint64_t>(p >> (extra > 100 ? 100 : extra)))
          << a << " * " << b << " >> " << extra;
      ASSERT_EQ(clocks, kB + 1 + static_cast<int>(extra));
    }
  }
}

TEST(RasterMul, AbortDropsTheProductInFlight) { check_abort<Vhtx_raster_mul>(kB / 2, kB + 1); }

// neg_i: the product negated, then shifted (the plane unit's gradient of a swapped triangle), on
// the operand extremes and random operands, in the same clocks.
TEST(RasterMul, NegatedProductsMatchExactProducts) {
  Mul<Vhtx_raster_mul> mul;
  auto& m = mul.model();
  const int64_t amin = -(int64_t{1} << (kA - 1)), amax = (int64_t{1} << (kA - 1)) - 1;
  const int64_t bmin = -(int64_t{1} << (kB - 1)), bmax = (int64_t{1} << (kB - 1)) - 1;
  std::vector<std::pair<int64_t, int64_t>> cases;
  for (int64_t a : {amin, amin + 1, int64_t{-1}, int64_t{0}, int64_t{1}, amax}) {
    for (int64_t b : {bmin, bmin + 1, int64_t{-1}, int64_t{0}, int64_t{1}, bmax}) cases.emplace_back(a, b);
  }
  std::mt19937_64 rng(11);
  for (int i = 0; i < 2000; ++i) cases.emplace_back(random_a(rng), random_b(rng));
  int clocks = 0;
  m.neg_i = 1;
  for (unsigned extra : {0u, 1u, 23u}) {
    for (const auto& [a, b] : cases) {
      const htx::model::i128 p = -(static_cast<htx::model::i128>(a) * b);
      ASSERT_EQ(mul.product(a, b, &clocks, extra), static_cast<uint64_t>(p >> extra))
          << "-(" << a << " * " << b << ") >> " << extra;
      ASSERT_EQ(clocks, kB + 1 + static_cast<int>(extra));
    }
  }
  // And back to positive products.
  m.neg_i = 0;
  EXPECT_EQ(mul.product(amin, bmin, &clocks), expected(amin, bmin));
}

// Digit-serial: a in 15-bit digits (38 bits: 3), b in 15-bit digits (26 bits: 2) or whole; one
// digit pair per clock, the first in the clock that takes start_i.
template <class V>
void check_digit_products(int pairs) {
  // Digit boundaries too: a lower digit all ones, a top digit of -1 or 0.
  check_products<V>(pairs, {(int64_t{1} << 15) - 1, int64_t{1} << 30, -(int64_t{1} << 30), (int64_t{1} << 30) - 1},
                    {(int64_t{1} << 15) - 1, -(int64_t{1} << 15)});
  Mul<V> mul;
  int clocks = 0;
  std::mt19937_64 rng(5);
  // extra_i shifts the product right (combinationally here).
  for (unsigned extra : {1u, 15u, 63u}) {
    const int64_t a = random_a(rng), b = random_b(rng);
    const htx::model::i128 p = static_cast<htx::model::i128>(a) * b;
    EXPECT_EQ(mul.product(a, b, &clocks, extra), static_cast<uint64_t>(p >> extra)) << extra;
  }
}

TEST(RasterMul, DigitSerialProductsMatchExactProducts) { check_digit_products<Vhtx_raster_mul_digits>(6); }

TEST(RasterMul, DigitSerialWithWholeBMatchesExactProducts) {
  check_digit_products<Vhtx_raster_mul_digits_wide_b>(3);
}

// The divider's use: start_i stays high and the operands change in the clock done_o is seen; each
// product is the new operands'.
template <class V>
void check_back_to_back() {
  Mul<V> mul;
  auto& m = mul.model();
  std::mt19937_64 rng(99);
  int64_t a = random_a(rng), b = random_b(rng);
  mul.operands(a, b);
  m.start_i = 1;
  int got = 0;
  for (int n = 0; n < 400 && got < 20; ++n) {
    mul.clock();
    if (m.done_o) {
      ASSERT_EQ(m.p_o, expected(a, b)) << "product " << got;
      ++got;
      a = random_a(rng);
      b = random_b(rng);
      mul.operands(a, b);
    }
  }
  EXPECT_EQ(got, 20);
}

TEST(RasterMul, DigitSerialBackToBackAndAbort) {
  check_back_to_back<Vhtx_raster_mul_digits>();
  check_back_to_back<Vhtx_raster_mul_digits_wide_b>();
  // Abort after two digit pairs.
  check_abort<Vhtx_raster_mul_digits>(2, 6);
  check_abort<Vhtx_raster_mul_digits_wide_b>(2, 3);
}

}  // namespace
