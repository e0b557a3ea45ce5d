// htx_raster_counters Verilated alone (eight 32-bit counters as 16-bit halves in one block RAM):
// every read returns the exact count of the events up to three clocks before its acknowledge (zero
// in the two clocks after a clear), within 2N + 1 clocks of asking; a clear zeroes every counter; an idle bank's state stands still, so a bank whose clock stops while
// idle (the simulated SoC's GPU clock gate) behaves as one clocked throughout (label `rtl`).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "Vhtx_raster_counters.h"
#include "vmodel_clock.hpp"

namespace {

constexpr int kN = 8;
using Counts = std::array<uint32_t, kN>;

// The bank with a reference count: counts_after[k] holds every counter after clock edge k.
class Bank {
 public:
  Bank() {
    m_.clear_i = 0;
    m_.inc_i = 0;
    m_.rd_i = 0;
    m_.rd_idx_i = 0;
    htx::raster_test::reset_model(m_);
    counts_after_.push_back(Counts{});
    cleared_at_.push_back(false);
  }

  // One clock with these inputs. Returns whether the read (if any) was acknowledged in it, and
  // checks the value it returned.
  bool clock(uint8_t inc, bool clear, bool rd, int idx) {
    m_.inc_i = inc;
    m_.clear_i = clear;
    m_.rd_i = rd;
    m_.rd_idx_i = static_cast<uint8_t>(idx);
    m_.eval();
    const bool ack = rd && m_.rd_ack_o;
    if (ack) {
      // This clock is number counts_after_.size(); the value counts the events up to three clocks
      // before it, i.e. after edge size() - 3 (and zero before the first edges), except that a
      // clear in one of the two clocks before already shows.
      const size_t t = counts_after_.size();
      const bool cleared = cleared_at_[t - 1] || (t >= 2 && cleared_at_[t - 2]);
      const uint32_t want = (t >= 3 && !cleared) ? counts_after_[t - 3][idx] : 0;
      EXPECT_EQ(m_.rd_data_o, want) << "counter " << idx << " read at clock " << t;
      last_value = m_.rd_data_o;
    }
    htx::raster_test::clock_edge(m_);
    Counts c = counts_after_.back();
    for (int i = 0; i < kN; ++i) {
      c[i] = clear ? 0 : c[i] + ((inc >> i) & 1);
    }
    counts_after_.push_back(c);
    cleared_at_.push_back(clear);
    return ack;
  }

  // Reads counter idx (no events meanwhile); returns the clocks it waited, value in last_value.
  int read(int idx) {
    for (int n = 1; n < 100; ++n) {
      if (clock(0, false, true, idx)) return n;
    }
    ADD_FAILURE() << "read of counter " << idx << " never acknowledged";
    return 100;
  }

  const Counts& now() const { return counts_after_.back(); }
  uint32_t last_value = 0;

 private:
  Vhtx_raster_counters m_;
  std::vector<Counts> counts_after_;
  std::vector<bool> cleared_at_;  // cleared_at_[k]: clear_i was set in the clock ending at edge k
};

TEST(RasterCounters, ReadsDuringRandomEventsAreExactThreeClocksBack) {
  std::mt19937 rng(7);
  Bank bank;
  bool reading = false;
  int idx = 0, waited = 0, worst = 0, reads = 0;
  for (int t = 0; t < 20000; ++t) {
    // Dense and sparse phases; counter 0 (CNT_BUSY) counts most clocks, as in the unit.
    const bool dense = (t / 1000) % 2 == 0;
    uint8_t inc = 0;
    for (int i = 0; i < kN; ++i) {
      if ((i == 0 && dense) || rng() % (dense ? 2 : 9) == 0) inc |= static_cast<uint8_t>(1 << i);
    }
    const bool clear = rng() % 1500 == 0;
    if (!reading && rng() % 3 == 0) {
      reading = true;
      idx = static_cast<int>(rng() % kN);
      waited = 0;
    }
    ++waited;
    if (bank.clock(inc, clear, reading, idx)) {
      reading = false;
      worst = std::max(worst, waited);
      ++reads;
    }
  }
  EXPECT_GT(reads, 1500);
  EXPECT_LE(worst, 2 * kN + 1) << "a read waits at most 2N + 1 clocks";
}

TEST(RasterCounters, IdleReadsAreExactAndAClearZeroesEveryCounter) {
  std::mt19937 rng(11);
  Bank bank;
  // Idle means no event for the three clocks a value lags.
  auto idle = [&] {
    for (int t = 0; t < 3; ++t) bank.clock(0, false, false, 0);
  };
  for (int t = 0; t < 500; ++t) bank.clock(static_cast<uint8_t>(rng()), false, false, 0);
  idle();
  for (int i = 0; i < kN; ++i) {
    bank.read(i);
    EXPECT_EQ(bank.last_value, bank.now()[i]) << "counter " << i;
    EXPECT_GT(bank.last_value, 200u) << "counter " << i;
  }
  // Past 2^16: the carry from the low half into the high half.
  for (int t = 0; t < 70000; ++t) bank.clock(0x01, false, false, 0);
  idle();
  bank.read(0);
  EXPECT_EQ(bank.last_value, bank.now()[0]);
  EXPECT_GT(bank.last_value, 65536u);
  bank.clock(0xFF, true, false, 0);  // a clear: its own clock's events are not counted
  for (int i = 0; i < kN; ++i) {
    bank.read(i);
    EXPECT_EQ(bank.last_value, 0u) << "counter " << i;
  }
  for (int t = 0; t < 37; ++t) bank.clock(static_cast<uint8_t>(1u << (t % kN)), false, false, 0);
  idle();
  for (int i = 0; i < kN; ++i) {
    bank.read(i);
    EXPECT_EQ(bank.last_value, bank.now()[i]) << "counter " << i;
  }
}

// Two banks see the same events; one keeps clocking through an idle gap, the other's clock stops
// there (as the SoC's gate stops an idle GPU after its hold time). Every later read must return the
// same value after the same wait.
TEST(RasterCounters, AnIdleBankStandsStillSoAStoppedClockChangesNothing) {
  std::mt19937 rng(5);
  Bank free_running, gated;
  auto both = [&](uint8_t inc, bool rd, int idx) {
    const bool a = free_running.clock(inc, false, rd, idx);
    const bool b = gated.clock(inc, false, rd, idx);
    EXPECT_EQ(a, b);
    return a;
  };
  for (int round = 0; round < 20; ++round) {
    const int busy = 5 + static_cast<int>(rng() % 40);
    for (int t = 0; t < busy; ++t) both(static_cast<uint8_t>(rng()), false, 0);
    for (int t = 0; t < 2 * kN + 3; ++t) both(0, false, 0);  // the gate's hold time covers this
    const int gap = 1 + static_cast<int>(rng() % 20);
    for (int t = 0; t < gap; ++t) free_running.clock(0, false, false, 0);  // gated: no clock
    const int idx = static_cast<int>(rng() % kN);
    EXPECT_EQ(free_running.read(idx), gated.read(idx)) << "round " << round;
    EXPECT_EQ(free_running.last_value, gated.last_value) << "round " << round;
    EXPECT_EQ(gated.last_value, gated.now()[idx]) << "round " << round;
  }
}

}  // namespace
