// htx_fb_ram's SPRAM form (the board's framebuffer: colour in two lanes of 9,600 words, depth in
// two blocks of 16K words stacked by address) against a reference memory: random reads and
// per-lane writes, never both in one clock (the single port's rule, which htx_fb keeps), each
// read's data checked in the clock after it and held until the next read (label `rtl`).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "Vhtx_fb_ram_tb.h"
#include "vmodel_clock.hpp"

namespace {

constexpr uint32_t kDepthWords = 19200;

TEST(FbRamSpram, ReadsWhatWasWrittenInBothShapes) {
  Vhtx_fb_ram_tb p;
  p.clk_i = 0;
  p.re_i = 0;
  p.we_i = 0;
  p.eval();
  // The colour memory sees an address's low 14 bits (the test bench wires them), so its reference
  // has 16K words: the colour SPRAM block holds them all, its 9,600 and the rest.
  std::vector<uint32_t> color(16384, 0);
  std::vector<uint16_t> depth(kDepthWords, 0);
  auto write = [&](uint32_t a, unsigned lanes, uint32_t d) {
    p.we_i = lanes;
    p.waddr_i = a;
    p.wdata_i = d;
    uint32_t& c = color[a & 0x3FFF];
    if (lanes & 1) {
      c = (c & 0xFFFF0000u) | (d & 0xFFFFu);
      depth[a] = static_cast<uint16_t>(d);
    }
    if (lanes & 2) c = (c & 0x0000FFFFu) | (d & 0xFFFF0000u);
  };
  // Every word written first, so each read has a defined reference.
  for (uint32_t a = 0; a < kDepthWords; ++a) {
    write(a, 3, a * 0x9E3779B9u);
    htx::raster_test::clock_edge(p);
  }
  p.we_i = 0;

  std::mt19937 rng(20261204);
  uint32_t want_color = 0, want_depth = 0;
  bool have_read = false;
  int reads = 0, high_bank_reads = 0;
  for (int i = 0; i < 60000; ++i) {
    const unsigned op = rng() % 4;  // 0, 1: read; 2: write; 3: idle
    p.re_i = 0;
    p.we_i = 0;
    if (op < 2) {
      const uint32_t a = rng() % kDepthWords;
      p.re_i = 1;
      p.raddr_i = a;
      want_color = color[a & 0x3FFF];
      want_depth = depth[a];
      high_bank_reads += a >= 16384;
      ++reads;
    } else if (op == 2) {
      write(rng() % kDepthWords, rng() % 4, rng());
    }
    htx::raster_test::clock_edge(p);
    if (op < 2) have_read = true;
    if (have_read) {
      ASSERT_EQ(p.color_rdata_o, want_color) << "clock " << i;
      ASSERT_EQ(p.depth_rdata_o, want_depth) << "clock " << i;
    }
  }
  EXPECT_GT(reads, 20000);
  EXPECT_GT(high_bank_reads, 3000);  // the second depth block is read too
}

}  // namespace
