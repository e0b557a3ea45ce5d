// htx_recip Verilated alone as the `icebreaker` divider's unit used it while it also served the
// time-multiplexed setup (until 2026-12-07): the FSM form with the serial normaliser (one bit a
// clock), X of 47 bits (setup's determinant, alt_i: 2 Newton steps) or of 42 bits brought shifted
// left by NormSkip = 5 (a pixel's Q: 1 step, or the table only). The divider now builds the unit
// with X = Q and neither input; the raster scene tests cover that form.
// Every result against the model's reciprocal (value and shift), for X with its leading one at
// every position, and the clocks each normalisation takes (label `rtl`).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "Vhtx_recip_serial.h"
#include "htx/model/recip.hpp"
#include "vmodel_clock.hpp"

namespace {

// The Verilated parameters (tests/rtl/raster/CMakeLists.txt).
constexpr unsigned kX = 47, kW = 24, kK = 8, kG = 2, kSkip = 5;
constexpr unsigned kSteps = 1, kAltSteps = 2;

struct Result {
  uint64_t r = 0;
  unsigned msb = 0;
  int clocks = 0;  // from the clock that takes start_i to the one that shows done_o
};

class Recip {
 public:
  Recip() {
    m_.abort_i = 0;
    m_.start_i = 0;
    m_.en_i = 1;
    m_.table_only_i = 0;
    m_.alt_i = 0;
    m_.mul_done_i = 0;
    m_.mul_p_i = 0;
    htx::raster_test::reset_model(m_);
  }
  void clock() { htx::raster_test::clock_edge(m_); }
  // x is X itself; a start without alt_i gets it shifted left by kSkip, as the divider sends it.
  Result run(uint64_t x, bool alt, bool table_only) {
    m_.x_i = alt ? x : x << kSkip;
    m_.alt_i = alt;
    m_.table_only_i = table_only;
    m_.start_i = 1;
    clock();
    m_.start_i = 0;
    Result res;
    res.clocks = 1;
    while (!m_.done_o && res.clocks < 1000) {
      clock();
      ++res.clocks;
    }
    res.r = table_only ? m_.r0_o : m_.r_o;
    res.msb = m_.msb_o;
    clock();
    EXPECT_FALSE(m_.done_o) << "done_o is a one-clock pulse";
    return res;
  }
  Vhtx_recip_serial& model() { return m_; }

 private:
  Vhtx_recip_serial m_;
};

// The normaliser's clocks for X: one shift a clock until the top bit is set or kX - 1 shifts are
// done (counting the kSkip a pixel's Q arrives with).
int norm_clocks(uint64_t x, bool alt) {
  unsigned n = alt ? 0 : kSkip;
  uint64_t v = alt ? x : x << kSkip;
  const uint64_t top = uint64_t{1} << (kX - 1), mask = (uint64_t{1} << kX) - 1;
  int clocks = 0;
  while (!(v & top) && n != kX - 1) {
    v = (v << 1) & mask;
    ++n;
    ++clocks;
  }
  return clocks;
}

void expect_model(const Result& got, uint64_t x, unsigned steps) {
  htx::model::RecipParams p;
  p.k = kK;
  p.g = kG;
  p.width = kW;
  p.steps = steps;
  const htx::model::Reciprocal want = htx::model::reciprocal(p, x);
  EXPECT_EQ(got.r, want.value) << "X = " << x << ", " << steps << " steps";
  EXPECT_EQ(static_cast<int>(got.msb + kW), want.shift) << "X = " << x;
}

TEST(RasterRecip, SerialNormalisationMatchesTheModelAtEveryLeadingOne) {
  Recip unit;
  std::mt19937_64 rng(20261202);
  // Setup's X (47 bits, AltSteps) and a pixel's Q (42 bits, Steps, or the table only).
  const struct { bool alt, table_only; unsigned bits, steps; } kinds[] = {
      {true, false, kX, kAltSteps}, {false, false, kX - kSkip, kSteps}, {false, true, kX - kSkip, 0}};
  for (const auto& kind : kinds) {
    // The clocks of an X whose top bit needs no shift: the rest of the unit's work.
    const uint64_t full = uint64_t{1} << (kind.bits - 1);
    const int base = unit.run(full, kind.alt, kind.table_only).clocks - norm_clocks(full, kind.alt);
    for (unsigned msb = 0; msb < kind.bits; ++msb) {
      for (int i = 0; i < 20; ++i) {
        const uint64_t low = msb == 0 ? 0 : rng() & ((uint64_t{1} << msb) - 1);
        const uint64_t x = (uint64_t{1} << msb) | (i == 0 ? 0 : i == 1 ? low | ((uint64_t{1} << msb) - 1) : low);
        const Result got = unit.run(x, kind.alt, kind.table_only);
        expect_model(got, x, kind.steps);
        EXPECT_EQ(got.clocks, base + norm_clocks(x, kind.alt)) << "X = " << x;
      }
    }
  }
}

TEST(RasterRecip, SerialNormalisationTakesOneClockPerShift) {
  // Setup's X with its leading one at bit m takes 46 - m clocks more than one at the top; a pixel's
  // Q, which arrives five bits up, 41 - m (at most 41 for Q = 1).
  Recip unit;
  const int base_alt = unit.run(uint64_t{1} << (kX - 1), true, false).clocks;
  const int base_pix = unit.run(uint64_t{1} << (kX - kSkip - 1), false, false).clocks;
  for (unsigned msb = 0; msb < kX; ++msb) {
    EXPECT_EQ(unit.run(uint64_t{1} << msb, true, false).clocks - base_alt, static_cast<int>(kX - 1 - msb))
        << "msb " << msb;
  }
  for (unsigned msb = 0; msb < kX - kSkip; ++msb) {
    EXPECT_EQ(unit.run(uint64_t{1} << msb, false, false).clocks - base_pix,
              static_cast<int>(kX - kSkip - 1 - msb))
        << "msb " << msb;
  }
}

TEST(RasterRecip, ZeroGivesMsbZeroAndTheUnitStaysUsable) {
  Recip unit;
  const Result zero = unit.run(0, true, false);
  EXPECT_EQ(zero.msb, 0u);
  expect_model(unit.run(12345, true, false), 12345, kAltSteps);
}

TEST(RasterRecip, AbortDuringNormalisationLeavesItIdle) {
  Recip unit;
  auto& m = unit.model();
  m.x_i = 1;  // the longest normalisation
  m.alt_i = 1;
  m.start_i = 1;
  unit.clock();
  m.start_i = 0;
  unit.clock();
  m.abort_i = 1;
  unit.clock();
  m.abort_i = 0;
  unit.clock();
  EXPECT_FALSE(m.busy_o);
  EXPECT_FALSE(m.done_o);
  expect_model(unit.run(987654321, true, false), 987654321, kAltSteps);
}

}  // namespace
