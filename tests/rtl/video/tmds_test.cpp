// htx_tmds_encoder, one DVI channel, against the specification's algorithm (tmds_reference.hpp) on
// random data in runs of data and blanking periods, with what a receiver relies on checked on the
// symbols themselves: each decodes to the value sent and the channel's running disparity stays
// bounded (label `rtl`).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>

#include "Vhtx_tmds_encoder.h"
#include "tmds_reference.hpp"
#include "vmodel_clock.hpp"

namespace {

using htx::video_test::TmdsEncoder;

struct Channel {
  Vhtx_tmds_encoder v;
  Channel() { htx::raster_test::reset_model(v); }
  // One clock: the symbol of (de, data, ctrl), one clock later as the encoder registers it.
  uint16_t clock(bool de, uint8_t data, unsigned ctrl) {
    v.de_i = de;
    v.data_i = data;
    v.ctrl_i = ctrl;
    htx::raster_test::clock_edge(v);
    return static_cast<uint16_t>(v.sym_o);
  }
};

TEST(Tmds, EveryByteFromEveryDisparityMatchesTheSpecification) {
  // Each of the 256 values sent after each prefix that leaves a different running disparity.
  for (unsigned prefix = 0; prefix < 256; ++prefix) {
    for (unsigned value = 0; value < 256; ++value) {
      Channel ch;
      TmdsEncoder ref;
      ch.clock(false, 0, 0);
      ref.encode(false, 0, 0);
      ASSERT_EQ(ch.clock(true, static_cast<uint8_t>(prefix), 0), ref.encode(true, static_cast<uint8_t>(prefix), 0));
      ASSERT_EQ(ch.clock(true, static_cast<uint8_t>(value), 0), ref.encode(true, static_cast<uint8_t>(value), 0))
          << "value " << value << " after " << prefix;
    }
  }
}

TEST(Tmds, RandomStreamsDecodeAndStayBalanced) {
  Channel ch;
  TmdsEncoder ref;
  std::mt19937 rng(20261205);
  int line_disparity = 0, worst = 0;
  uint64_t data_symbols = 0, transitions = 0, raw_transitions = 0;
  for (int run = 0; run < 400; ++run) {
    const bool de = (run % 2) == 0;
    const int length = 1 + static_cast<int>(rng() % 700);
    const int style = static_cast<int>(rng() % 3);  // random bytes, a gradient, one repeated value
    const uint8_t base = static_cast<uint8_t>(rng());
    if (!de) line_disparity = 0;
    for (int i = 0; i < length; ++i) {
      const uint8_t data = style == 0   ? static_cast<uint8_t>(rng())
                           : style == 1 ? static_cast<uint8_t>(base + i)
                                        : base;
      const unsigned ctrl = rng() & 3;
      const uint16_t sym = ch.clock(de, data, ctrl);
      ASSERT_EQ(sym, ref.encode(de, data, ctrl)) << "run " << run << " symbol " << i;
      const htx::video_test::TmdsSymbol got = htx::video_test::tmds_decode(sym);
      ASSERT_EQ(got.de, de);
      if (de) {
        ASSERT_EQ(got.data, data);
        line_disparity += htx::video_test::tmds_balance(sym);
        worst = std::max(worst, std::abs(line_disparity));
        ASSERT_EQ(line_disparity, ref.disparity());
        ++data_symbols;
        transitions += static_cast<unsigned>(std::popcount(static_cast<unsigned>((sym ^ (sym >> 1)) & 0xFFu)));
        raw_transitions += static_cast<unsigned>(std::popcount(static_cast<unsigned>((data ^ (data >> 1)) & 0x7Fu)));
      } else {
        ASSERT_EQ(got.ctrl, ctrl);
      }
    }
  }
  // The disparity the encoder tracks is the symbols' own, and it stays small (the 6-bit register).
  EXPECT_LE(worst, 16);
  EXPECT_GT(data_symbols, 50000u);
  // Transition minimisation: fewer transitions inside the symbols' eight data bits than in the data.
  EXPECT_LT(transitions, raw_transitions);
}

}  // namespace
