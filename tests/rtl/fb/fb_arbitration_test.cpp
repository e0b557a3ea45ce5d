// htx_fb's arbitration (docs/raster.md, "htx_fb") in both port forms against a reference memory:
// random raster traffic (depth reads, colour and depth writes to any colour page), video scan-out
// reads, and a bus master that holds each request until it is taken, all at once. Checked every
// clock: the video port's grant rule, each bus request answered exactly once in the clock after it
// is taken, with its error flag and the data as the memory held it before that clock's writes (a
// read of a word being written gives the old word), and the raster's depth reads and the video
// reads likewise. The two-port form's video port is built by no SoC (its GPU has no scan-out), so
// only this test reaches it. A single-ported memory given a read and a write in one clock stops the
// model ($error; Verilator's fatalOnError). Label `rtl`.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "Vhtx_fb_1p.h"
#include "Vhtx_fb_2p.h"
#include "vmodel_clock.hpp"

namespace {

// Both models: 64 pixels (32 colour words a page), 16-bit depth (CMakeLists.txt).
constexpr uint32_t kPixels = 64;
constexpr uint32_t kPageWords = kPixels / 2;
constexpr uint32_t kColorBase = 0x30000000u;
constexpr uint32_t kDepthBase = 0x30100000u;

struct Counts {
  uint64_t bus_color_reads = 0, bus_color_writes = 0, bus_depth_reads = 0, bus_depth_writes = 0;
  uint64_t bus_errors = 0, video_reads = 0, depth_reads = 0, bus_waits = 0;
  uint64_t read_of_word_written = 0;  // a bus or video read of a colour word the raster writes then
};

template <class Model>
void run_traffic(bool single_port, uint32_t pages, uint32_t seed, uint32_t clocks, Counts& n) {
  Model m;
  std::mt19937 rng(seed);
  auto chance = [&](unsigned percent) { return rng() % 100 < percent; };
  std::vector<uint32_t> color(pages * kPageWords, 0);
  std::vector<uint16_t> depth(kPixels, 0);

  m.zr_en_i = m.wc_en_i = m.wz_en_i = m.vr_req_i = m.req_valid_i = 0;
  htx::raster_test::reset_model(m);

  // The bus request being offered (held until taken), and what each answer must be.
  bool offering = false;
  uint32_t addr = 0, wdata = 0;
  bool we = false;
  unsigned be = 0xF;
  struct Expect {
    bool bus = false, bus_err = false, bus_read = false, zr = false, vr = false;
    uint32_t bus_data = 0, zr_data = 0, vr_data = 0;
  };

  for (uint32_t clock = 0; clock < clocks; ++clock) {
    // ---- This clock's inputs.
    if (!offering && chance(60)) {
      offering = true;
      we = chance(50);
      be = chance(70) ? 0xF : (rng() & 0xF);
      wdata = rng();
      const unsigned kind = rng() % 100;
      if (kind < 45) {
        addr = kColorBase + 4 * (rng() % (pages * kPageWords));
      } else if (kind < 80) {
        addr = kDepthBase + 4 * (rng() % kPixels);
      } else if (kind < 88) {  // just past either memory
        addr = (chance(50) ? kColorBase + 4 * pages * kPageWords : kDepthBase + 4 * kPixels) +
               4 * (rng() % 8);
      } else {  // another window of the GPU's address space: never a memory
        addr = 0x30200000u + 4 * (rng() % 64);
      }
      addr |= rng() & 3;  // the low bits are ignored
    }
    m.req_valid_i = offering;
    m.req_addr_i = addr;
    m.req_we_i = we;
    m.req_be_i = be;
    m.req_wdata_i = wdata;

    m.zr_en_i = chance(35);
    m.zr_addr_i = rng() % kPixels;
    m.wc_en_i = chance(35);
    // The single-ported fragment stage never reads and writes depth in one clock.
    m.wz_en_i = chance(35) && !(single_port && m.zr_en_i);
    m.w_addr_i = rng() % kPixels;
    m.wc_data_i = rng() & 0xFFFF;
    m.wz_data_i = rng() & 0xFFFF;
    m.c_page_i = rng() % pages;
    m.vr_req_i = chance(40);
    m.vr_addr_i = rng() % (pages * kPageWords);
    m.eval();

    // ---- The arbitration's decisions in this clock.
    const bool vr_gnt = m.vr_gnt_o;
    ASSERT_EQ(vr_gnt, m.vr_req_i && !(single_port && m.wc_en_i))
        << "clock " << clock << ": the video read waits only for a single port's colour write";
    const bool taken = offering && m.req_ready_o;
    if (offering && !taken) ++n.bus_waits;

    // ---- The answers due next clock, from the memory as it is before this clock's writes.
    const uint32_t raster_word = (m.w_addr_i >> 1) + m.c_page_i * kPageWords;
    Expect next;
    if (m.zr_en_i) {
      next.zr = true;
      next.zr_data = depth[m.zr_addr_i];
      ++n.depth_reads;
    }
    if (vr_gnt) {
      next.vr = true;
      next.vr_data = color[m.vr_addr_i];
      ++n.video_reads;
      if (m.wc_en_i && raster_word == m.vr_addr_i) ++n.read_of_word_written;
    }
    bool bus_color_write = false, bus_depth_write = false;
    uint32_t bus_word = 0;
    if (taken) {
      const uint32_t window = addr >> 20;
      bus_word = (addr & 0xFFFFF) >> 2;
      const bool is_color = window == (kColorBase >> 20);
      const bool is_depth = window == (kDepthBase >> 20);
      const bool in_range = (is_color && bus_word < pages * kPageWords) || (is_depth && bus_word < kPixels);
      next.bus = true;
      next.bus_err = !in_range;
      next.bus_read = !we;
      if (!in_range) {
        ++n.bus_errors;
      } else if (we) {
        bus_color_write = is_color;
        bus_depth_write = is_depth && be == 0xF;  // a partial depth write is taken and ignored
        ++(is_color ? n.bus_color_writes : n.bus_depth_writes);
        // The raster's ports come first: a bus write never shares a clock with its memory's write.
        ASSERT_FALSE(is_color && m.wc_en_i) << "clock " << clock;
        ASSERT_FALSE(is_depth && m.wz_en_i) << "clock " << clock;
      } else {
        next.bus_data = is_color ? color[bus_word] : depth[bus_word];
        ++(is_color ? n.bus_color_reads : n.bus_depth_reads);
        if (is_color && m.wc_en_i && raster_word == bus_word) ++n.read_of_word_written;
        ASSERT_FALSE(is_color && vr_gnt) << "clock " << clock << ": the video read goes first";
        ASSERT_FALSE(is_depth && m.zr_en_i) << "clock " << clock << ": the raster's depth read goes first";
      }
      if (single_port && in_range) {
        ASSERT_FALSE(is_color && (m.wc_en_i || vr_gnt)) << "clock " << clock;
        ASSERT_FALSE(is_depth && (m.zr_en_i || m.wz_en_i)) << "clock " << clock;
      }
      offering = false;
    }

    // ---- This clock's writes.
    if (m.wc_en_i) {
      uint32_t& w = color.at(raster_word);
      w = (m.w_addr_i & 1) ? (w & 0x0000FFFFu) | (uint32_t{m.wc_data_i} << 16)
                           : (w & 0xFFFF0000u) | m.wc_data_i;
    }
    if (m.wz_en_i) depth[m.w_addr_i] = static_cast<uint16_t>(m.wz_data_i);
    if (bus_color_write) {
      uint32_t& w = color[bus_word];
      if ((be & 0x3) == 0x3) w = (w & 0xFFFF0000u) | (wdata & 0xFFFFu);
      if ((be & 0xC) == 0xC) w = (w & 0x0000FFFFu) | (wdata & 0xFFFF0000u);
    }
    if (bus_depth_write) depth[bus_word] = static_cast<uint16_t>(wdata);

    htx::raster_test::clock_edge(m);

    // ---- The answers of the clock just taken.
    ASSERT_EQ(bool(m.rsp_valid_o), next.bus) << "clock " << clock << ": one answer a taken request";
    if (next.bus) {
      EXPECT_EQ(bool(m.rsp_err_o), next.bus_err) << "clock " << clock << " address 0x" << std::hex << addr;
      if (next.bus_read) {
        EXPECT_EQ(m.rsp_rdata_o, next.bus_err ? 0u : next.bus_data)
            << "clock " << clock << " address 0x" << std::hex << addr;
      }
    }
    if (next.zr) {
      EXPECT_EQ(m.zr_data_o, next.zr_data) << "clock " << clock;
    }
    if (next.vr) {
      EXPECT_EQ(m.vr_data_o, next.vr_data) << "clock " << clock;
    }
    if (::testing::Test::HasFailure()) return;
  }
}

// Each path must have been exercised, or the test proves nothing about it. Only two ports read a
// colour word in the clock the raster writes it (one port waits for the write).
void expect_coverage(const Counts& n, bool single_port) {
  EXPECT_GT(n.bus_color_reads, 500u);
  EXPECT_GT(n.bus_color_writes, 500u);
  EXPECT_GT(n.bus_depth_reads, 500u);
  EXPECT_GT(n.bus_depth_writes, 500u);
  EXPECT_GT(n.bus_errors, 500u);
  EXPECT_GT(n.video_reads, 5000u);
  EXPECT_GT(n.depth_reads, 5000u);
  EXPECT_GT(n.bus_waits, 500u);
  std::printf("bus: %llu colour reads, %llu colour writes, %llu depth reads, %llu depth writes, "
              "%llu errors, %llu clocks waiting; %llu video reads, %llu raster depth reads, "
              "%llu reads of a word being written\n",
              (unsigned long long)n.bus_color_reads, (unsigned long long)n.bus_color_writes,
              (unsigned long long)n.bus_depth_reads, (unsigned long long)n.bus_depth_writes,
              (unsigned long long)n.bus_errors, (unsigned long long)n.bus_waits,
              (unsigned long long)n.video_reads, (unsigned long long)n.depth_reads,
              (unsigned long long)n.read_of_word_written);
  if (single_port) {
    EXPECT_EQ(n.read_of_word_written, 0u);
  } else {
    EXPECT_GT(n.read_of_word_written, 50u);
  }
}

TEST(FbArbitration, TwoPortsServeRasterVideoAndBusTogether) {
  Counts n;
  run_traffic<Vhtx_fb_2p>(false, 2, 20261207, 40000, n);
  expect_coverage(n, false);
}

TEST(FbArbitration, SinglePortServesRasterVideoAndBusTogether) {
  Counts n;
  run_traffic<Vhtx_fb_1p>(true, 3, 20261208, 40000, n);
  expect_coverage(n, true);
}

}  // namespace
