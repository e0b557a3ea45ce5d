// htx_raster_lut_divider Verilated alone with the board's parameters (Q of 42 bits, numerators of
// 55, a 24-bit mantissa, an 8-bit table with 2 guard bits, 10 fraction bits out): every quotient
// against the model's divide_fixed with the table value alone (RECIP_LUT), bit for bit, for Q with
// its leading one at every position and quotients up to the 13-bit texel range; fragments that need
// no division pass with the last quotients kept; the payload travels with its fragment; an abort
// mid-division leaves the next division exact (label `rtl`). The scene tests reach the numerators'
// own rounding (N' = round(N 2^-s)) too rarely to catch it missing, so this test does.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "Vhtx_raster_lut_divider.h"
#include "htx/model/recip.hpp"
#include "vmodel_clock.hpp"

namespace {

// The Verilated parameters (tests/rtl/raster/CMakeLists.txt).
constexpr unsigned kQ = 42, kU = 55, kW = 24, kK = 8, kG = 2, kTF = 10;
constexpr uint64_t kQMask = (uint64_t{1} << kQ) - 1, kUMask = (uint64_t{1} << kU) - 1;

struct Out {
  int32_t u = 0, v = 0;
  uint32_t pay = 0;
  int clocks = 0;  // from the clock that takes the fragment to the first one with out_valid_o
};

class Divider {
 public:
  Divider() {
    m_.abort_i = 0;
    m_.in_valid_i = 0;
    m_.in_need_i = 0;
    m_.out_ready_i = 0;
    htx::raster_test::reset_model(m_);
  }
  void clock() { htx::raster_test::clock_edge(m_); }
  Out run(int64_t q, int64_t u, int64_t v, bool need, uint32_t pay) {
    m_.in_q_i = static_cast<uint64_t>(q) & kQMask;
    m_.in_u_i = static_cast<uint64_t>(u) & kUMask;
    m_.in_v_i = static_cast<uint64_t>(v) & kUMask;
    m_.in_need_i = need;
    m_.in_pay_i = pay;
    m_.in_valid_i = 1;
    m_.eval();
    EXPECT_TRUE(m_.in_ready_o) << "idle divider takes a fragment";
    clock();
    m_.in_valid_i = 0;
    Out o;
    o.clocks = 1;
    m_.eval();
    while (!m_.out_valid_o && o.clocks < 200) {
      clock();
      ++o.clocks;
    }
    EXPECT_TRUE(m_.out_valid_o) << "no result after 200 clocks";
    o.u = static_cast<int32_t>(m_.out_u_o);
    o.v = static_cast<int32_t>(m_.out_v_o);
    o.pay = m_.out_pay_o;
    m_.out_ready_i = 1;
    clock();
    m_.out_ready_i = 0;
    m_.eval();
    EXPECT_FALSE(m_.out_valid_o) << "the result leaves when taken";
    return o;
  }
  Vhtx_raster_lut_divider& model() { return m_; }

 private:
  Vhtx_raster_lut_divider m_;
};

int64_t expected(int64_t num, int64_t q) {
  const htx::model::RecipParams p{kK, kG, kW, 0};
  return htx::model::divide_fixed(p, num, q < 1 ? 1 : q, kTF);
}

// A numerator whose quotient by q is about `texels` (|texels| < 2^12), with random low bits.
int64_t numerator(std::mt19937_64& rng, int64_t q, double texels) {
  const double n = texels * static_cast<double>(q);
  std::uniform_int_distribution<int64_t> jitter(-1000, 1000);
  return static_cast<int64_t>(n) + jitter(rng);
}

TEST(RasterLutDivider, MatchesTheModelForEveryLeadingOne) {
  Divider d;
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> texels(-4000.0, 4000.0);
  int checked = 0;
  for (unsigned msb = 0; msb < kQ - 1; ++msb) {
    for (int i = 0; i < 300; ++i) {
      const uint64_t low = msb == 0 ? 0 : rng() & ((uint64_t{1} << msb) - 1);
      const int64_t q = static_cast<int64_t>((uint64_t{1} << msb) | low);
      const int64_t u = numerator(rng, q, texels(rng)), v = numerator(rng, q, texels(rng));
      const Out o = d.run(q, u, v, true, static_cast<uint32_t>(i) & 0xFF);
      ASSERT_EQ(o.u, expected(u, q)) << "q " << q << " u " << u;
      ASSERT_EQ(o.v, expected(v, q)) << "q " << q << " v " << v;
      // Normalisation (one shift a clock), the last shift's clock, six digit products, the hand-over.
      EXPECT_EQ(o.clocks, static_cast<int>(kQ - 1 - msb) + 9) << "q " << q;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 300 * static_cast<int>(kQ - 1));
}

TEST(RasterLutDivider, RoundsTheShiftedNumeratorAsTheModelDoes) {
  // Numerators whose bit s - 1 (the rounding bit of N 2^-s) is set, at quotients where the carry it
  // adds decides the result's last bit: found by searching, so the test shows that such cases occur.
  Divider d;
  std::mt19937_64 rng(7);
  int differs = 0;
  for (int i = 0; i < 2000000 && differs < 50; ++i) {
    const unsigned msb = kW + static_cast<unsigned>(rng() % (kQ - 1 - kW));  // s > 0
    const int64_t q = static_cast<int64_t>((uint64_t{1} << msb) | (rng() & ((uint64_t{1} << msb) - 1)));
    const int64_t u = numerator(rng, q, static_cast<double>(static_cast<int64_t>(rng() % 8000) - 4000) / 3.0);
    const int s = static_cast<int>(msb) - static_cast<int>(kW - 1);
    // Without N's own rounding: floor(N 2^-s) in place of round(N 2^-s).
    const htx::model::RecipParams p{kK, kG, kW, 0};
    int dummy = 0;
    const uint64_t m = htx::model::normalise(static_cast<htx::model::u128>(q), kW, &dummy);
    const htx::model::i128 n_floor = static_cast<htx::model::i128>(u) >> s;
    const htx::model::i128 prod = n_floor * static_cast<htx::model::i128>(htx::model::recip_mantissa(p, m));
    const int sh = 2 * static_cast<int>(kW) - 1 - static_cast<int>(kTF);
    const int64_t truncated = static_cast<int64_t>((prod + (static_cast<htx::model::i128>(1) << (sh - 1))) >> sh);
    if (truncated == expected(u, q)) continue;
    ++differs;
    const Out o = d.run(q, u, -u, true, 0);
    ASSERT_EQ(o.u, expected(u, q)) << "q " << q << " u " << u;
    ASSERT_EQ(o.v, expected(-u, q)) << "q " << q << " v " << -u;
  }
  EXPECT_GE(differs, 10) << "too few numerators whose own rounding decides the quotient";
}

TEST(RasterLutDivider, QBelowOneDividesByOne) {
  Divider d;
  for (const int64_t q : {int64_t{0}, int64_t{-1}, -(int64_t{1} << 40)}) {
    const Out o = d.run(q, 12345, -678, true, 0);
    EXPECT_EQ(o.u, expected(12345, 1));
    EXPECT_EQ(o.v, expected(-678, 1));
  }
}

TEST(RasterLutDivider, FragmentsWithoutDivisionPassAndKeepTheLastQuotients) {
  Divider d;
  const int64_t q = int64_t{1} << 30;
  const Out first = d.run(q, int64_t{5} << 30, int64_t{-3} << 30, true, 0x11);
  EXPECT_EQ(first.u, expected(int64_t{5} << 30, q));
  EXPECT_EQ(first.pay, 0x11u);
  const Out pass = d.run(1, 999, 999, false, 0x22);
  EXPECT_EQ(pass.clocks, 1);
  EXPECT_EQ(pass.u, first.u);
  EXPECT_EQ(pass.v, first.v);
  EXPECT_EQ(pass.pay, 0x22u);
}

TEST(RasterLutDivider, AnAbortMidDivisionLeavesTheNextExact) {
  Divider d;
  auto& m = d.model();
  m.in_q_i = 3;  // a long normalisation
  m.in_u_i = 77;
  m.in_v_i = 88;
  m.in_need_i = 1;
  m.in_valid_i = 1;
  d.clock();
  m.in_valid_i = 0;
  for (int i = 0; i < 10; ++i) d.clock();
  m.abort_i = 1;
  d.clock();
  m.abort_i = 0;
  m.eval();
  EXPECT_FALSE(m.out_valid_o);
  EXPECT_TRUE(m.in_ready_o);
  const int64_t q = (int64_t{1} << 35) + 12345;
  const Out o = d.run(q, int64_t{700} << 35, int64_t{-9} << 35, true, 0x33);
  EXPECT_EQ(o.u, expected(int64_t{700} << 35, q));
  EXPECT_EQ(o.v, expected(int64_t{-9} << 35, q));
  EXPECT_EQ(o.pay, 0x33u);
}

}  // namespace
