// htx_soc_fabric (interconnect, RAM, SYSCTRL, UART, TIMER, GPU) driven directly on the CPU's two bus
// ports: unmapped accesses, RAM throughput and byte lanes, each peripheral, the UART's serial line
// (internal loopback and the real pins), the timer compare, the GPU's registers and memory windows,
// and random wait states on every slave.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>

#include <cstdint>
#include <string>
#include <vector>

#include "fabric_harness.hpp"
#include "htx/fw/plane_record.h"
#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/image_io.hpp"
#include "htx/sim/uart_line.hpp"
#include "htx/sim/video_capture.hpp"
#include "htx_regs.h"

namespace {

using htx::test::BusReq;
using htx::test::FabricHarness;

constexpr uint32_t kSys = HTX_SYSCTRL_BASE;
constexpr uint32_t kUart = HTX_UART_BASE;
constexpr uint32_t kTimer = HTX_TIMER_BASE;
constexpr uint32_t kRaster = HTX_RASTER_BASE;
constexpr uint32_t kTexture = HTX_TEXTURE_BASE;
constexpr uint32_t kRamBytes = 65536;  // the Verilated fabric's RamBytes
constexpr uint32_t kFbColor = 0x3000'0000, kFbDepth = 0x3010'0000, kTexMem = 0x4000'0000;
constexpr uint32_t kFbPixels = 19200;  // the fabric's default FbPixels (160 x 120)

uint32_t lcg(uint32_t& s) { return s = s * 1664525u + 1013904223u; }

class FabricTest : public ::testing::TestWithParam<int> {
 protected:
  // Parameter 0: no wait states; otherwise the stall seed.
  FabricTest() : soc(GetParam() != 0, static_cast<uint32_t>(GetParam())) {}
  FabricHarness soc;
};

TEST_P(FabricTest, UnmappedAccessesCompleteWithErrorAndNothingHangs) {
  const uint32_t holes[] = {0x1000'0000, kRamBytes, 0x2000'7000, 0x2FFF'FFFC, 0x5000'0000, 0xFFFF'FFFC};
  for (uint32_t a : holes) {
    const auto r = soc.read(a);
    EXPECT_TRUE(r.err) << std::hex << a;
    EXPECT_EQ(r.rdata, 0u) << std::hex << a;
    EXPECT_TRUE(soc.write(a, 0x1234'5678).err) << std::hex << a;
  }
  // The instruction port reaches the RAM only: a hole and every register block answer an error
  // (code runs from RAM; the register blocks are on the data port), and the port still works.
  const uint32_t not_code[] = {0x6000'0000, kSys, kUart, kTimer, kRaster, kTexture};
  for (uint32_t a : not_code) soc.ibus.pending.push_back({a});
  soc.ibus.pending.push_back({0x0000'0100});
  ASSERT_TRUE(soc.drain());
  ASSERT_EQ(soc.ibus.responses.size(), std::size(not_code) + 1);
  for (size_t i = 0; i < std::size(not_code); ++i) {
    EXPECT_TRUE(soc.ibus.responses[i].err) << std::hex << not_code[i];
    EXPECT_EQ(soc.ibus.responses[i].rdata, 0u) << std::hex << not_code[i];
  }
  EXPECT_FALSE(soc.ibus.responses.back().err);
  // Back-to-back error, RAM, error on the data port: in order, each with its own outcome.
  const size_t base = soc.dbus.responses.size();
  soc.dbus.pending.push_back({0x1000'0000});
  soc.dbus.pending.push_back({0x0000'0040, true, 0xF, 77});
  soc.dbus.pending.push_back({0x0000'0040});
  soc.dbus.pending.push_back({0x7000'0000});
  ASSERT_TRUE(soc.drain());
  ASSERT_EQ(soc.dbus.responses.size(), base + 4);
  EXPECT_TRUE(soc.dbus.responses[base].err);
  EXPECT_FALSE(soc.dbus.responses[base + 1].err);
  EXPECT_EQ(soc.dbus.responses[base + 2].rdata, 77u);
  EXPECT_TRUE(soc.dbus.responses[base + 3].err);
}

TEST_P(FabricTest, GpuRegistersAndMemoryWindows) {
  // RASTER registers on the data port; like every register block, not on the instruction port
  // (code runs from RAM only): a fetch answers an error with 0.
  EXPECT_EQ(soc.read(kRaster + RASTER_FB_SIZE_Offset).rdata, RASTER_FB_SIZE_RESET);
  soc.ibus.pending.push_back({kRaster + RASTER_FB_STRIDE_Offset});
  ASSERT_TRUE(soc.drain());
  ASSERT_TRUE(soc.ibus.responses.back().err);
  EXPECT_EQ(soc.ibus.responses.back().rdata, 0u);
  // Colour window: words of two RGB565 pixels, half-word lanes; depth window: one pixel a word, 16 bits.
  ASSERT_FALSE(soc.write(kFbColor + 8, 0x1111'2222).err);
  soc.write(kFbColor + 8, 0xAAAA'0000, 0xC);
  EXPECT_EQ(soc.read(kFbColor + 8).rdata, 0xAAAA'2222u);
  // Three colour pages (triple buffering) of kFbPixels pixels, kFbPixels / 2 words, each.
  const uint32_t colour_end = kFbColor + 4 * (3 * kFbPixels / 2);
  soc.write(colour_end - 4, 0xBEEF'CAFE);  // the last word of page 2
  EXPECT_EQ(soc.read(colour_end - 4).rdata, 0xBEEF'CAFEu);
  ASSERT_FALSE(soc.write(kFbDepth + 4 * 17, 0x0001'2345).err);
  EXPECT_EQ(soc.read(kFbDepth + 4 * 17).rdata & 0xFFFFu, 0x2345u);
  ASSERT_FALSE(soc.write(kFbDepth + 4 * (kFbPixels - 1), 0x0000'6789).err);  // the last pixel
  const auto last_depth = soc.read(kFbDepth + 4 * (kFbPixels - 1));
  ASSERT_FALSE(last_depth.err);
  EXPECT_EQ(last_depth.rdata & 0xFFFFu, 0x6789u);
  // TEXTURE registers and the texture memory (4 words per 2x2 block, TEXEL_BITS stored per word).
  const auto caps = soc.read(kTexture + TEXTURE_CAPS_Offset);
  ASSERT_FALSE(caps.err);
  EXPECT_EQ((caps.rdata & TEXTURE_CAPS_SLOTS_Msk) >> TEXTURE_CAPS_SLOTS_Pos, 4u);  // icebreaker
  const uint32_t tex_bytes = 16u << ((caps.rdata & TEXTURE_CAPS_BLOCK_BITS_Msk) >> TEXTURE_CAPS_BLOCK_BITS_Pos);
  const uint32_t texel_bits = (caps.rdata & TEXTURE_CAPS_TEXEL_BITS_Msk) >> TEXTURE_CAPS_TEXEL_BITS_Pos;
  ASSERT_GE(texel_bits, 16u);
  const uint32_t texel_mask = texel_bits >= 32 ? 0xFFFF'FFFFu : (1u << texel_bits) - 1;
  ASSERT_FALSE(soc.write(kTexMem + 4, 0x0000'1234).err);
  ASSERT_FALSE(soc.write(kTexMem + tex_bytes - 4, 0x0000'ABCD).err);
  // The board's texture memory is written only (CAPS.WINDOW_READ = 0): a read answers an error
  // with 0 at once, whatever was written (the scene tests sample what the writes stored).
  EXPECT_EQ(caps.rdata & TEXTURE_CAPS_WINDOW_READ_Msk, 0u);
  EXPECT_NE(texel_mask, 0u);
  for (uint32_t a : {kTexMem + 4, kTexMem + tex_bytes - 4}) {
    const auto r = soc.read(a);
    EXPECT_TRUE(r.err) << std::hex << a;
    EXPECT_EQ(r.rdata, 0u) << std::hex << a;
  }
  // Beyond the memories and holes of the windows answer errors.
  for (uint32_t a : {colour_end, kFbDepth + 4 * kFbPixels, 0x3020'0000u, kTexMem + tex_bytes,
                     kTexMem + 0x10'0000u, 0x2000'6000u}) {
    const auto r = soc.read(a);
    EXPECT_TRUE(r.err) << std::hex << a;
    EXPECT_EQ(r.rdata, 0u) << std::hex << a;
  }
  // The memory windows are data only: a fetch from them answers an error.
  for (uint32_t a : {kFbColor + 8, kTexMem + 4}) {
    soc.ibus.pending.push_back({a});
    ASSERT_TRUE(soc.drain());
    EXPECT_TRUE(soc.ibus.responses.back().err) << std::hex << a;
  }
  // The raster unit draws into the memory the windows show: a fast clear of a 16 x 4 screen.
  soc.write(kRaster + RASTER_FB_SIZE_Offset, 16u | (4u << RASTER_FB_SIZE_HEIGHT_Pos));
  soc.write(kRaster + RASTER_FB_STRIDE_Offset, 16u);
  soc.write(kRaster + RASTER_CLEAR_COLOR_Offset, 0x5A5Au);
  soc.write(kRaster + RASTER_CLEAR_DEPTH_Offset, 0x0123u);
  soc.write(kRaster + RASTER_CTRL_Offset, RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk | RASTER_CTRL_CLEAR_DEPTH_Msk);
  // Polls STATUS until the raster unit is idle, at most `polls` times.
  const auto raster_idle = [&](int polls) {
    for (int i = 0; i < polls; ++i)
      if (!(soc.read(kRaster + RASTER_STATUS_Offset).rdata & RASTER_STATUS_BUSY_Msk)) return true;
    return false;
  };
  ASSERT_TRUE(raster_idle(2000));
  for (uint32_t w = 0; w < 32; ++w) EXPECT_EQ(soc.read(kFbColor + 4 * w).rdata, 0x5A5A'5A5Au) << w;
  EXPECT_EQ(soc.read(kFbColor + 4 * 32).rdata, 0u);  // pixel 64: outside the 16 x 4 screen
  EXPECT_EQ(soc.read(kFbDepth + 4 * 63).rdata & 0xFFFFu, 0x0123u);
  // This fabric's GPU is the board's (CMakeLists.txt): AFFINE and RECIP_LUT, no raster counters,
  // setup in firmware (plane records). Every CNT_* then answers 0 at once, after the clear above
  // as after a counter reset.
  EXPECT_EQ(soc.read(kRaster + RASTER_CAPS_Offset).rdata,
            (0b00101u << RASTER_CAPS_METHODS_Pos) | RASTER_CAPS_FW_SETUP_Msk);
  for (uint32_t off = RASTER_CNT_BUSY_Offset; off <= RASTER_CNT_DIVFREE_STEPS_Offset; off += 4) {
    const auto r = soc.read(kRaster + off);
    EXPECT_FALSE(r.err) << std::hex << off;
    EXPECT_EQ(r.rdata, 0u) << std::hex << off;
  }
  soc.write(kRaster + RASTER_CTRL_Offset, RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_COUNTERS_RESET_Msk);
  EXPECT_EQ(soc.read(kRaster + RASTER_CNT_BUSY_Offset).rdata, 0u);
  // Nor STATE (CAPS.STATE = 0, checked with CAPS above): after a triangle it still reads 0.
  htx::fw::VertexIn in[3] = {};
  const double xy[3][2] = {{1, 1}, {14, 1}, {1, 3}};
  for (int i = 0; i < 3; ++i) {
    in[i].x = xy[i][0];
    in[i].y = xy[i][1];
    in[i].z = 0.5;
    in[i].w = 1;
    in[i].r = in[i].g = in[i].b = in[i].a = 1;
  }
  htx::fw::TriangleRecord rec;
  ASSERT_EQ(htx::fw::encode_triangle(htx::model_config("icebreaker").record_format(), in, &rec),
            htx::fw::kEncodeOk);
  // Set up as the firmware does for a unit with CAPS.FW_SETUP: a plane record.
  htx::fw::PlaneJob job;
  job.params = &htx::fw::kIcebreakerSetup;
  job.width = 16;
  job.height = 4;
  job.state_word = (5u << RASTER_STATE_DEPTH_FUNC_Pos) | RASTER_STATE_GOURAUD_Msk;
  uint32_t words[htx::fw::kPlaneRecordMaxWords];
  size_t n = 0;
  ASSERT_EQ(htx::fw::encode_plane_record(job, rec, words, &n), htx::fw::kPlaneOk);
  for (size_t i = 0; i < n; ++i) soc.write(kRaster + RASTER_FIFO_Offset, words[i]);
  ASSERT_TRUE(raster_idle(20000));
  EXPECT_EQ(soc.read(kRaster + RASTER_STATUS_Offset).rdata & RASTER_STATUS_ERR_STATE_Msk, 0u);
  EXPECT_EQ(soc.read(kFbColor + 4 * 9).rdata & 0xFFFFu, 0xFFFFu);  // pixel (2, 1) of the 16 x 4 screen: white
  EXPECT_EQ(soc.read(kRaster + RASTER_STATE_Offset).rdata, 0u);
}

TEST_P(FabricTest, RamByteLanes) {
  ASSERT_FALSE(soc.write(0x100, 0x1122'3344).err);
  soc.write(0x100, 0x0000'00AA, 0x1);  // sb to byte 0
  soc.write(0x100, 0xBB00'0000, 0x8);  // sb to byte 3
  EXPECT_EQ(soc.read(0x100).rdata, 0xBB22'33AAu);
  soc.write(0x100, 0xCCDD'0000, 0xC);  // sh to the upper half
  EXPECT_EQ(soc.read(0x100).rdata, 0xCCDD'33AAu);
  soc.write(kRamBytes - 4, 0xCAFE'F00D);  // the last word
  EXPECT_EQ(soc.read(kRamBytes - 4).rdata, 0xCAFE'F00Du);
}

TEST_P(FabricTest, FetchAndDataRunInParallel) {
  constexpr int kWords = 64;
  for (int i = 0; i < kWords; ++i) soc.dbus.pending.push_back({0x1000u + 4u * i, true, 0xF, 0xA000'0000u + i});
  ASSERT_TRUE(soc.drain());
  const uint64_t start = soc.cycle();
  const size_t d0 = soc.dbus.responses.size();
  for (int i = 0; i < kWords; ++i) {
    soc.ibus.pending.push_back({0x1000u + 4u * i});
    soc.dbus.pending.push_back({0x2000u + 4u * i, true, 0xF, 0xB000'0000u + i});
  }
  ASSERT_TRUE(soc.drain());
  for (int i = 0; i < kWords; ++i) {
    EXPECT_EQ(soc.ibus.responses[i].rdata, 0xA000'0000u + i);
    EXPECT_FALSE(soc.dbus.responses[d0 + i].err);
  }
  if (GetParam() == 0) {
    // One access per clock on each port at once: the RAM is dual-ported, latency 1.
    EXPECT_LE(soc.cycle() - start, static_cast<uint64_t>(kWords + 1));
  }
  for (int i = 0; i < kWords; i += 7) EXPECT_EQ(soc.read(0x2000u + 4u * i).rdata, 0xB000'0000u + i);
}

TEST_P(FabricTest, SysctrlRegisters) {
  EXPECT_EQ(soc.read(kSys + SYSCTRL_ID_Offset).rdata, SYSCTRL_ID_RESET);
  EXPECT_EQ(soc.read(kSys + SYSCTRL_VERSION_Offset).rdata, SYSCTRL_VERSION_RESET);
  EXPECT_EQ(soc.read(kSys + SYSCTRL_CLOCK_HZ_Offset).rdata, 12'000'000u);
  EXPECT_EQ(soc.read(kSys + SYSCTRL_PLATFORM_Offset).rdata & SYSCTRL_PLATFORM_SIM_Msk, SYSCTRL_PLATFORM_SIM_Msk);
  soc.write(kSys + SYSCTRL_SCRATCH_Offset, 0xDEAD'BEEF);
  soc.write(kSys + SYSCTRL_SCRATCH_Offset, 0x0000'5500, 0x2);
  EXPECT_EQ(soc.read(kSys + SYSCTRL_SCRATCH_Offset).rdata, 0xDEAD'55EFu);
  // SIM_EXIT: a one-clock strobe with the code.
  soc.dbus.pending.push_back({kSys + SYSCTRL_SIM_EXIT_Offset, true, 0xF, 42});
  bool seen = false;
  for (int i = 0; i < 200 && !seen; ++i) {
    soc.step();
    if (soc.sim_exit_strobe()) {
      seen = true;
      EXPECT_EQ(soc.sim_exit_code(), 42);
    }
  }
  EXPECT_TRUE(seen);
}

// Register blocks are decoded by word, as the CPU addresses them: a byte or half-word access at an
// address inside a register reaches that register's lanes (SYSCTRL SCRATCH's bytes, UART CTRL's
// LOOPBACK byte at +2; a read anywhere in a word returns the word, whose lane the CPU's load unit
// picks). Until 2026-12-06 every block compared the whole address, so such accesses hit nothing
// and answered OK. The raster FIFO takes whole words only (a narrower write is refused with a bus
// error and nothing is pushed), and a word it could never take (the unit disabled, the FIFO full:
// nothing drains it) is refused with a bus error at once instead of holding the bus for ever.
TEST_P(FabricTest, SubWordRegisterAccessesAndTheRasterFifosRefusals) {
  soc.write(kSys + SYSCTRL_SCRATCH_Offset, 0x1122'3344);
  EXPECT_FALSE(soc.write(kSys + SYSCTRL_SCRATCH_Offset + 2, 0x00AB'0000, 0x4).err);  // sb, lane 2
  EXPECT_EQ(soc.read(kSys + SYSCTRL_SCRATCH_Offset + 3).rdata, 0x11AB'3344u);
  EXPECT_FALSE(soc.write(kSys + SYSCTRL_SCRATCH_Offset + 2, 0xCDEF'0000, 0xC).err);  // sh, upper half
  EXPECT_EQ(soc.read(kSys + SYSCTRL_SCRATCH_Offset + 2).rdata, 0xCDEF'3344u);
  const uint32_t uart_ctrl = soc.read(kUart + UART_CTRL_Offset).rdata;
  ASSERT_EQ(uart_ctrl & UART_CTRL_LOOPBACK_Msk, 0u);
  EXPECT_FALSE(soc.write(kUart + UART_CTRL_Offset + 2, UART_CTRL_LOOPBACK_Msk, 0x4).err);
  EXPECT_EQ(soc.read(kUart + UART_CTRL_Offset + 1).rdata, uart_ctrl | UART_CTRL_LOOPBACK_Msk);
  soc.write(kUart + UART_CTRL_Offset, uart_ctrl);
  for (uint32_t lane = 1; lane < 4; ++lane) {
    EXPECT_EQ(soc.read(kRaster + RASTER_CAPS_Offset + lane).rdata, soc.read(kRaster + RASTER_CAPS_Offset).rdata);
    EXPECT_EQ(soc.read(kTimer + TIMER_CTRL_Offset + lane).rdata, soc.read(kTimer + TIMER_CTRL_Offset).rdata);
    EXPECT_EQ(soc.read(kSys + SYSCTRL_ID_Offset + lane).rdata, SYSCTRL_ID_RESET);
  }

  const auto fifo_empty = [this] {
    return (soc.read(kRaster + RASTER_STATUS_Offset).rdata & RASTER_STATUS_FIFO_EMPTY_Msk) != 0;
  };
  ASSERT_TRUE(fifo_empty());
  EXPECT_TRUE(soc.write(kRaster + RASTER_FIFO_Offset, 0x0000'1234, 0x3).err);  // sh
  EXPECT_TRUE(soc.write(kRaster + RASTER_FIFO_Offset + 1, 0x0000'5600, 0x2).err);  // sb
  EXPECT_TRUE(fifo_empty()) << "a partial write was pushed";
  soc.write(kRaster + RASTER_CTRL_Offset, 0);  // disabled: nothing leaves the FIFO
  int pushed = 0;
  while (!(soc.read(kRaster + RASTER_STATUS_Offset).rdata & RASTER_STATUS_FIFO_FULL_Msk) && pushed < 4096) {
    ASSERT_FALSE(soc.write(kRaster + RASTER_FIFO_Offset, 0).err);
    ++pushed;
  }
  ASSERT_LT(pushed, 4096);
  const uint64_t before = soc.cycle();
  EXPECT_TRUE(soc.write(kRaster + RASTER_FIFO_Offset, 0).err);
  EXPECT_LT(soc.cycle() - before, 100u);
  EXPECT_TRUE(soc.read(kRaster + RASTER_STATUS_Offset).rdata & RASTER_STATUS_FIFO_FULL_Msk);
  soc.write(kRaster + RASTER_CTRL_Offset, RASTER_CTRL_ABORT_Msk | RASTER_CTRL_ENABLE_Msk);
  EXPECT_TRUE(fifo_empty());
}

// Reads STATUS until `mask` is set, at most `limit` reads.
bool wait_status(FabricHarness& soc, uint32_t mask, int limit = 20000) {
  for (int i = 0; i < limit; ++i) {
    if (soc.read(kUart + UART_STATUS_Offset).rdata & mask) return true;
  }
  return false;
}

TEST_P(FabricTest, UartLoopbackFifosAndOverrun) {
  const uint32_t st = soc.read(kUart + UART_STATUS_Offset).rdata;
  EXPECT_EQ(st & (UART_STATUS_TX_EMPTY_Msk | UART_STATUS_TX_IDLE_Msk | UART_STATUS_RX_VALID_Msk),
            UART_STATUS_TX_EMPTY_Msk | UART_STATUS_TX_IDLE_Msk);
  EXPECT_EQ(soc.read(kUart + UART_CTRL_Offset).rdata, UART_CTRL_RESET);
  EXPECT_EQ(soc.read(kUart + UART_DATA_Offset).rdata, UART_DATA_RX_EMPTY_Msk);  // empty: nothing popped
  soc.write(kUart + UART_CTRL_Offset, 8u | UART_CTRL_LOOPBACK_Msk);

  // 20 bytes queued back to back: the TX FIFO holds 16, so later writes wait (stall the bus) for
  // room and none is lost; the receiver keeps 16 and flags the rest as overrun.
  const std::string msg = "The quick brown fox!";
  for (char c : msg) soc.dbus.pending.push_back({kUart + UART_DATA_Offset, true, 0x1, static_cast<uint8_t>(c)});
  const size_t first = soc.dbus.responses.size();
  ASSERT_TRUE(soc.drain(200000));
  // 16 bytes fit in the FIFO and one more in the shifter; the 18th write could only be accepted once
  // the shifter had sent a byte (10 bits of 8 clocks).
  EXPECT_LT(soc.dbus.responses[first + 16].cycle - soc.dbus.responses[first].cycle, 8u * 10);
  EXPECT_GT(soc.dbus.responses[first + 17].cycle - soc.dbus.responses[first + 16].cycle, 8u * 5);
  ASSERT_TRUE(wait_status(soc, UART_STATUS_TX_IDLE_Msk));
  for (int i = 0; i < 50; ++i) soc.step();  // the last stop bit reaches the receiver
  const uint32_t level = soc.read(kUart + UART_LEVEL_Offset).rdata;
  EXPECT_EQ((level & UART_LEVEL_RX_Msk) >> UART_LEVEL_RX_Pos, 16u);
  EXPECT_EQ((level & UART_LEVEL_TX_Msk) >> UART_LEVEL_TX_Pos, 0u);
  const uint32_t st2 = soc.read(kUart + UART_STATUS_Offset).rdata;
  EXPECT_TRUE(st2 & UART_STATUS_RX_FULL_Msk);
  EXPECT_TRUE(st2 & UART_STATUS_RX_OVERRUN_Msk);
  EXPECT_FALSE(st2 & UART_STATUS_RX_FRAME_ERR_Msk);
  // A byte read of RX_EMPTY's lane (lbu DATA + 1, as the CPU issues it) tests for a byte and pops
  // nothing: the next word read still gets the first byte.
  soc.dbus.pending.push_back({kUart + UART_DATA_Offset + 1, false, 0x2, 0});
  ASSERT_TRUE(soc.drain());
  EXPECT_FALSE(soc.dbus.responses.back().rdata & UART_DATA_RX_EMPTY_Msk);
  EXPECT_EQ((soc.read(kUart + UART_LEVEL_Offset).rdata & UART_LEVEL_RX_Msk) >> UART_LEVEL_RX_Pos, 16u);
  std::string got;
  for (int i = 0; i < 16; ++i) {
    const uint32_t d = soc.read(kUart + UART_DATA_Offset).rdata;
    ASSERT_FALSE(d & UART_DATA_RX_EMPTY_Msk);
    got += static_cast<char>(d & 0xFF);
  }
  EXPECT_EQ(got, msg.substr(0, 16));
  EXPECT_TRUE(soc.read(kUart + UART_DATA_Offset).rdata & UART_DATA_RX_EMPTY_Msk);
  soc.write(kUart + UART_STATUS_Offset, UART_STATUS_RX_OVERRUN_Msk);  // write one to clear
  EXPECT_FALSE(soc.read(kUart + UART_STATUS_Offset).rdata & UART_STATUS_RX_OVERRUN_Msk);
  EXPECT_TRUE(soc.uart_tx()) << "in loopback the TX pin stays idle";
}

TEST_P(FabricTest, UartSerialPinsBothWaysAndFramingError) {
  constexpr uint32_t kDiv = 16;
  soc.write(kUart + UART_CTRL_Offset, kDiv);
  htx::sim::UartLineDecoder from_soc(kDiv);
  htx::sim::UartLineEncoder to_soc(kDiv);
  std::string heard;
  auto clock = [&](int n) {
    for (int i = 0; i < n; ++i) {
      soc.uart_rx = to_soc.step();
      soc.step();
      if (auto b = from_soc.step(soc.uart_tx())) heard += static_cast<char>(*b);
    }
  };
  for (char c : std::string("hi\n")) soc.dbus.pending.push_back({kUart + UART_DATA_Offset, true, 0x1, static_cast<uint8_t>(c)});
  for (char c : std::string("ok")) to_soc.push(static_cast<uint8_t>(c));
  clock(3 * 10 * kDiv + 200);
  EXPECT_EQ(heard, "hi\n");
  EXPECT_EQ(from_soc.framing_errors(), 0u);
  soc.dbus.responses.clear();
  EXPECT_EQ(soc.read(kUart + UART_DATA_Offset).rdata, static_cast<uint32_t>('o'));
  EXPECT_EQ(soc.read(kUart + UART_DATA_Offset).rdata, static_cast<uint32_t>('k'));

  // A frame whose stop bit is 0: dropped, RX_FRAME_ERR set until written with a one.
  const uint8_t byte = 0x5A;
  const int bits[10] = {0, byte & 1, (byte >> 1) & 1, (byte >> 2) & 1, (byte >> 3) & 1, (byte >> 4) & 1,
                        (byte >> 5) & 1, (byte >> 6) & 1, (byte >> 7) & 1, 0};
  for (int b : bits) {
    for (uint32_t k = 0; k < kDiv; ++k) {
      soc.uart_rx = b;
      soc.step();
    }
  }
  soc.uart_rx = true;
  for (int i = 0; i < 4 * static_cast<int>(kDiv); ++i) soc.step();
  const uint32_t st = soc.read(kUart + UART_STATUS_Offset).rdata;
  EXPECT_TRUE(st & UART_STATUS_RX_FRAME_ERR_Msk);
  EXPECT_FALSE(st & UART_STATUS_RX_VALID_Msk);
  soc.write(kUart + UART_STATUS_Offset, UART_STATUS_RX_FRAME_ERR_Msk);
  EXPECT_FALSE(soc.read(kUart + UART_STATUS_Offset).rdata & UART_STATUS_RX_FRAME_ERR_Msk);

  // A break (the line low for two and a half frames) is one framing error, no byte: the receiver
  // waits for the line to rise before it looks for a start bit, so neither the break nor the
  // bits around its end are taken for bytes, and the byte after it arrives whole.
  soc.uart_rx = false;
  for (uint32_t i = 0; i < 25 * kDiv + kDiv / 3; ++i) soc.step();
  soc.uart_rx = true;
  for (uint32_t i = 0; i < 2 * kDiv; ++i) soc.step();
  to_soc.push('A');
  clock(12 * kDiv);
  EXPECT_TRUE(soc.read(kUart + UART_STATUS_Offset).rdata & UART_STATUS_RX_FRAME_ERR_Msk);
  EXPECT_EQ(soc.read(kUart + UART_DATA_Offset).rdata, static_cast<uint32_t>('A'));
  EXPECT_TRUE(soc.read(kUart + UART_DATA_Offset).rdata & UART_DATA_RX_EMPTY_Msk);
  soc.write(kUart + UART_STATUS_Offset, UART_STATUS_RX_FRAME_ERR_Msk);

  // Every bit on the TX pin lasts exactly the divisor: 0x55 changes the line at each of the nine
  // bit boundaries from the start bit to the stop bit.
  soc.dbus.pending.push_back({kUart + UART_DATA_Offset, true, 0x1, 0x55});
  std::vector<uint64_t> edges;
  bool line = soc.uart_tx();
  for (int i = 0; i < 12 * static_cast<int>(kDiv) && edges.size() < 10; ++i) {
    soc.step();
    if (soc.uart_tx() != line) {
      line = soc.uart_tx();
      edges.push_back(soc.cycle());
    }
  }
  ASSERT_EQ(edges.size(), 10u);  // the start bit's falling edge and nine boundaries
  for (size_t i = 1; i < edges.size(); ++i) EXPECT_EQ(edges[i] - edges[i - 1], kDiv) << "bit " << i;
}

TEST_P(FabricTest, TimerCountsAndCompares) {
  const uint32_t t0 = soc.read(kTimer + TIMER_MTIME_LO_Offset).rdata;
  for (int i = 0; i < 100; ++i) soc.step();
  const uint32_t t1 = soc.read(kTimer + TIMER_MTIME_LO_Offset).rdata;
  EXPECT_GE(t1 - t0, 100u);
  EXPECT_EQ(soc.read(kTimer + TIMER_STATUS_Offset).rdata & TIMER_STATUS_MATCH_Msk, 0u);  // compare resets to all ones

  // A carry from the low into the high word.
  soc.write(kTimer + TIMER_MTIME_HI_Offset, 0);
  soc.write(kTimer + TIMER_MTIME_LO_Offset, 0xFFFF'FFF0u);
  for (int i = 0; i < 40; ++i) soc.step();
  EXPECT_EQ(soc.read(kTimer + TIMER_MTIME_HI_Offset).rdata, 1u);

  const uint32_t now = soc.read(kTimer + TIMER_MTIME_LO_Offset).rdata;
  soc.write(kTimer + TIMER_MTIMECMP_LO_Offset, now + 300);
  soc.write(kTimer + TIMER_MTIMECMP_HI_Offset, 1);
  soc.write(kTimer + TIMER_MTIMECMP_LO_Offset, 0x1234, 0x1);  // partial writes are ignored
  EXPECT_EQ(soc.read(kTimer + TIMER_MTIMECMP_LO_Offset).rdata, now + 300);
  soc.write(kTimer + TIMER_CTRL_Offset, TIMER_CTRL_ENABLE_Msk | TIMER_CTRL_IRQ_ENABLE_Msk);
  EXPECT_EQ(soc.read(kTimer + TIMER_STATUS_Offset).rdata & TIMER_STATUS_MATCH_Msk, 0u);
  EXPECT_FALSE(soc.timer_irq());
  int waited = 0;
  while (!soc.timer_irq() && waited < 2000) {
    soc.step();
    ++waited;
  }
  EXPECT_TRUE(soc.timer_irq());
  EXPECT_EQ(soc.read(kTimer + TIMER_STATUS_Offset).rdata & TIMER_STATUS_MATCH_Msk, TIMER_STATUS_MATCH_Msk);
  const uint32_t at = soc.read(kTimer + TIMER_MTIME_LO_Offset).rdata;
  EXPECT_GE(at - now, 300u);

  soc.write(kTimer + TIMER_CTRL_Offset, 0);  // stopped: the counter holds
  const uint32_t held = soc.read(kTimer + TIMER_MTIME_LO_Offset).rdata;
  for (int i = 0; i < 50; ++i) soc.step();
  EXPECT_EQ(soc.read(kTimer + TIMER_MTIME_LO_Offset).rdata, held);
  EXPECT_FALSE(soc.timer_irq());

  // Requests back to back, without waiting for responses: each acts after the one before, so a
  // read right behind a write sees it (the timer acts a clock after it accepts a request).
  soc.dbus.responses.clear();
  soc.dbus.pending.push_back({kTimer + TIMER_MTIMECMP_LO_Offset, true, 0xF, 0x1234'5678});
  soc.dbus.pending.push_back({kTimer + TIMER_MTIMECMP_LO_Offset});
  soc.dbus.pending.push_back({kTimer + TIMER_MTIME_HI_Offset, true, 0xF, 7});
  soc.dbus.pending.push_back({kTimer + TIMER_MTIME_LO_Offset, true, 0xF, 0xFFFF'FFFFu});
  soc.dbus.pending.push_back({kTimer + TIMER_MTIME_HI_Offset});
  soc.dbus.pending.push_back({kTimer + TIMER_MTIME_LO_Offset});
  soc.dbus.pending.push_back({kTimer + TIMER_MTIMECMP_LO_Offset, true, 0xF, 9});
  soc.dbus.pending.push_back({kTimer + TIMER_MTIMECMP_HI_Offset, true, 0xF, 0});
  soc.dbus.pending.push_back({kTimer + TIMER_STATUS_Offset});
  ASSERT_TRUE(soc.drain());
  ASSERT_EQ(soc.dbus.responses.size(), 9u);
  EXPECT_EQ(soc.dbus.responses[1].rdata, 0x1234'5678u);
  EXPECT_EQ(soc.dbus.responses[4].rdata, 7u);  // stopped: 0xFFFF_FFFF does not wrap into it
  EXPECT_EQ(soc.dbus.responses[5].rdata, 0xFFFF'FFFFu);
  EXPECT_EQ(soc.dbus.responses[8].rdata & TIMER_STATUS_MATCH_Msk, TIMER_STATUS_MATCH_Msk);

  // Counting again, the low word wraps into the high one in the same clock: the compare never
  // sees a value with a stale high word (7:FFFF_FFFF, then 8:0000_0000, never 7:0000_0000), so a
  // match from 7:FFFF_FFF8 on holds across the wrap.
  soc.write(kTimer + TIMER_MTIMECMP_HI_Offset, 7);
  soc.write(kTimer + TIMER_MTIMECMP_LO_Offset, 0xFFFF'FFF8u);
  soc.write(kTimer + TIMER_MTIME_LO_Offset, 0xFFFF'FFF0u);
  soc.write(kTimer + TIMER_CTRL_Offset, TIMER_CTRL_ENABLE_Msk | TIMER_CTRL_IRQ_ENABLE_Msk);
  uint64_t first_irq = 0;
  for (int i = 0; i < 60 && first_irq == 0; ++i) {
    soc.step();
    if (soc.timer_irq()) first_irq = soc.cycle();
  }
  ASSERT_NE(first_irq, 0u);
  for (int i = 0; i < 20; ++i) {
    soc.step();
    EXPECT_TRUE(soc.timer_irq()) << "the match holds once mtime has passed mtimecmp";
  }
  EXPECT_EQ(soc.read(kTimer + TIMER_MTIME_HI_Offset).rdata, 8u);
}

// Random traffic on both ports at once, checked against a model of memory: responses arrive in
// request order with the right data, whatever the wait states.
TEST_P(FabricTest, RandomTrafficOnBothPortsMatchesTheModel) {
  std::vector<uint32_t> model(1024);
  uint32_t s = 12345u + static_cast<uint32_t>(GetParam());
  for (uint32_t i = 0; i < model.size(); ++i) {
    model[i] = lcg(s);
    soc.dbus.pending.push_back({0x4000u + 4u * i, true, 0xF, model[i]});
  }
  ASSERT_TRUE(soc.drain());
  soc.ibus.responses.clear();
  soc.dbus.responses.clear();

  struct Expect {
    uint32_t rdata;
    bool err;
    bool check_data;
  };
  std::vector<Expect> want_i, want_d;
  uint32_t scratch = soc.read(kSys + SYSCTRL_SCRATCH_Offset).rdata;
  soc.dbus.responses.clear();
  for (int n = 0; n < 3000; ++n) {
    const uint32_t r = lcg(s);
    const uint32_t w = (r >> 8) % 512;  // the instruction port reads words 0..511, data writes 512..1023
    soc.ibus.pending.push_back({0x4000u + 4u * w});
    want_i.push_back({model[w], false, true});
    switch (r % 5) {
      case 0: {
        const uint32_t d = 512 + (r >> 16) % 512;
        const uint32_t v = lcg(s);
        soc.dbus.pending.push_back({0x4000u + 4u * d, true, 0xF, v});
        model[d] = v;
        want_d.push_back({0, false, false});
        break;
      }
      case 1: {
        const uint32_t d = 512 + (r >> 16) % 512;
        soc.dbus.pending.push_back({0x4000u + 4u * d});
        want_d.push_back({model[d], false, true});
        break;
      }
      case 2:
        soc.dbus.pending.push_back({kSys + SYSCTRL_SCRATCH_Offset, true, 0xF, r});
        scratch = r;
        want_d.push_back({0, false, false});
        break;
      case 3:
        soc.dbus.pending.push_back({kSys + SYSCTRL_SCRATCH_Offset});
        want_d.push_back({scratch, false, true});
        break;
      default:
        soc.dbus.pending.push_back({0x1000'0000u + (r & 0xFFC)});
        want_d.push_back({0, true, true});
        break;
    }
  }
  const uint64_t start = soc.cycle();
  ASSERT_TRUE(soc.drain(400000));
  ASSERT_EQ(soc.ibus.responses.size(), want_i.size());
  ASSERT_EQ(soc.dbus.responses.size(), want_d.size());
  for (size_t i = 0; i < want_i.size(); ++i) {
    ASSERT_EQ(soc.ibus.responses[i].rdata, want_i[i].rdata) << "ibus response " << i;
  }
  for (size_t i = 0; i < want_d.size(); ++i) {
    ASSERT_EQ(soc.dbus.responses[i].err, want_d[i].err) << "dbus response " << i;
    if (want_d[i].check_data) ASSERT_EQ(soc.dbus.responses[i].rdata, want_d[i].rdata) << "dbus response " << i;
  }
  if (GetParam() != 0) {
    EXPECT_GT(soc.cycle() - start, 3000u * 3 / 2) << "stall injection should have slowed the traffic";
  }
}

// VIDEO: the scan-out shows what the data port wrote into the colour window, every pixel of a
// frame as a 4 x 4 block, while the data port keeps reading that window (the video's reads go
// first on the colour memory; the bus's wait) and gets the right words back.
TEST_P(FabricTest, VideoShowsTheColourWindowWhileTheBusReadsIt) {
  constexpr uint32_t kVideo = HTX_VIDEO_BASE;
  EXPECT_EQ(soc.read(kVideo + VIDEO_MODE_Offset).rdata,
            160u | (120u << 12) | (4u << 24) | (3u << VIDEO_MODE_PAGES_Pos));
  std::vector<uint32_t> words(kFbPixels / 2);
  uint32_t seed = 99;
  for (uint32_t i = 0; i < words.size(); ++i) {
    words[i] = lcg(seed);
    soc.dbus.pending.push_back({kFbColor + 4 * i, true, 0xF, words[i]});
  }
  ASSERT_TRUE(soc.drain(1'000'000));
  ASSERT_FALSE(soc.write(kVideo + VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk).err);

  // To the next vertical sync, then one frame's visible pixels, with a colour read every 97 clocks.
  const size_t first_read = soc.dbus.responses.size();
  std::vector<uint32_t> read_index;
  htx::sim::VideoCapture monitor;
  for (uint64_t i = 0; i < 3ull * 800 * 525 && monitor.frames() == 0; ++i) {
    if (i % 97 == 0) {
      const uint32_t w = lcg(seed) % words.size();
      read_index.push_back(w);
      soc.dbus.pending.push_back({kFbColor + 4 * w});
    }
    soc.step();
    const htx::test::VideoPins v = soc.video();
    monitor.clock(v.de, v.vsync_n, v.rgb);
  }
  ASSERT_TRUE(soc.drain());
  const std::vector<uint32_t>& px = monitor.last_frame();
  ASSERT_EQ(px.size(), 640u * 480u);
  for (uint32_t y = 0; y < 480; ++y) {
    for (uint32_t x = 0; x < 640; ++x) {
      const uint32_t i = (y / 4) * 160 + x / 4;
      const auto p = static_cast<uint16_t>(words[i / 2] >> (16 * (i % 2)));
      ASSERT_EQ(px[y * 640 + x], htx::rgb888_from_rgb565(p)) << "x " << x << " y " << y;
    }
  }
  ASSERT_EQ(soc.dbus.responses.size(), first_read + read_index.size());
  for (size_t k = 0; k < read_index.size(); ++k) {
    EXPECT_FALSE(soc.dbus.responses[first_read + k].err);
    EXPECT_EQ(soc.dbus.responses[first_read + k].rdata, words[read_index[k]]) << "read " << k;
  }
  const uint32_t status = soc.read(kVideo + VIDEO_STATUS_Offset).rdata;
  EXPECT_EQ(status & VIDEO_STATUS_UNDERRUN_Msk, 0u);
  EXPECT_NE(status & VIDEO_STATUS_SHOWING_Msk, 0u);
}

// The raster unit's fast clear writes a pixel every clock for 19,200 clocks, six picture lines: it
// waits while the video reads (clear_hold_i), so clears back to back for two frames leave no line
// late, and the frame after them is the clear colour.
TEST_P(FabricTest, FastClearsYieldToTheVideoReads) {
  constexpr uint32_t kVideo = HTX_VIDEO_BASE;
  ASSERT_FALSE(soc.write(kVideo + VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk).err);
  soc.write(kRaster + RASTER_CLEAR_COLOR_Offset, 0xF81Fu);  // magenta
  for (uint64_t i = 0; i < 2ull * 800 * 525; i += 16000) {
    soc.write(kRaster + RASTER_CTRL_Offset, RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk);
    for (int k = 0; k < 16000; ++k) soc.step();
  }
  EXPECT_EQ(soc.read(kVideo + VIDEO_STATUS_Offset).rdata & VIDEO_STATUS_UNDERRUN_Msk, 0u);
  htx::sim::VideoCapture monitor;
  for (uint64_t i = 0; i < 3ull * 800 * 525 && monitor.frames() == 0; ++i) {
    soc.step();
    const htx::test::VideoPins v = soc.video();
    monitor.clock(v.de, v.vsync_n, v.rgb);
  }
  ASSERT_EQ(monitor.last_frame().size(), 640u * 480u);
  EXPECT_EQ(std::count(monitor.last_frame().begin(), monitor.last_frame().end(), 0xFF00FFu), 640 * 480);
}

// Triple buffering: the raster unit's fast clear goes to the page FB_PAGE.DRAW names while the
// video shows another; the flip to the drawn page is taken at the next frame's start. A page the
// memory does not have (3) leaves either register as it was.
TEST_P(FabricTest, DrawsIntoOnePageWhileTheVideoShowsAnother) {
  constexpr uint32_t kVideo = HTX_VIDEO_BASE;
  constexpr uint32_t kPageWords = kFbPixels / 2;
  EXPECT_EQ(soc.read(kRaster + RASTER_FB_MEM_Offset).rdata, kFbPixels | (3u << RASTER_FB_MEM_PAGES_Pos));
  EXPECT_EQ(soc.read(kRaster + RASTER_FB_PAGE_Offset).rdata, 0u);
  for (uint32_t i = 0; i < 2 * kPageWords; ++i) soc.dbus.pending.push_back({kFbColor + 4 * i, true, 0xF, 0xFFFF'FFFFu});
  ASSERT_TRUE(soc.drain(2'000'000));
  ASSERT_FALSE(soc.write(kVideo + VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk).err);
  ASSERT_FALSE(soc.write(kRaster + RASTER_FB_PAGE_Offset, 2u << RASTER_FB_PAGE_DRAW_Pos).err);
  ASSERT_FALSE(soc.write(kRaster + RASTER_FB_PAGE_Offset, 3u << RASTER_FB_PAGE_DRAW_Pos).err);
  EXPECT_EQ(soc.read(kRaster + RASTER_FB_PAGE_Offset).rdata, 2u << RASTER_FB_PAGE_DRAW_Pos) << "3 is ignored";
  soc.write(kRaster + RASTER_FB_SIZE_Offset, 160u | (120u << RASTER_FB_SIZE_HEIGHT_Pos));
  soc.write(kRaster + RASTER_FB_STRIDE_Offset, 160u);
  soc.write(kRaster + RASTER_CLEAR_COLOR_Offset, 0x07E0u);  // green
  soc.write(kRaster + RASTER_CTRL_Offset, RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk);
  const auto capture = [&] {
    htx::sim::VideoCapture monitor;
    for (uint64_t i = 0; i < 3ull * 800 * 525 && monitor.frames() == 0; ++i) {
      soc.step();
      const htx::test::VideoPins v = soc.video();
      monitor.clock(v.de, v.vsync_n, v.rgb);
    }
    return monitor.last_frame();
  };
  std::vector<uint32_t> px = capture();  // (the clear runs meanwhile)
  ASSERT_EQ(px.size(), 640u * 480u);
  EXPECT_EQ(std::count(px.begin(), px.end(), 0xFFFFFFu), 640 * 480) << "page 0 shown, untouched";
  EXPECT_EQ(soc.read(kRaster + RASTER_STATUS_Offset).rdata & RASTER_STATUS_BUSY_Msk, 0u);
  for (uint32_t w : {0u, 4799u, kPageWords - 1}) {
    EXPECT_EQ(soc.read(kFbColor + 4 * w).rdata, 0xFFFF'FFFFu) << w;
    EXPECT_EQ(soc.read(kFbColor + 4 * (kPageWords + w)).rdata, 0xFFFF'FFFFu) << "page 1 untouched " << w;
    EXPECT_EQ(soc.read(kFbColor + 4 * (2 * kPageWords + w)).rdata, 0x07E0'07E0u) << w;
  }
  const uint32_t page2 = 2u << VIDEO_CTRL_PAGE_Pos;
  ASSERT_FALSE(soc.write(kVideo + VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk | page2).err);
  ASSERT_FALSE(soc.write(kVideo + VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk | (3u << VIDEO_CTRL_PAGE_Pos)).err);
  EXPECT_EQ(soc.read(kVideo + VIDEO_CTRL_Offset).rdata, VIDEO_CTRL_ENABLE_Msk | page2) << "3 is ignored";
  px = capture();  // the frame under way when the flip was written, or the next
  px = capture();
  ASSERT_EQ(px.size(), 640u * 480u);
  EXPECT_EQ(std::count(px.begin(), px.end(), 0x00FF00u), 640 * 480) << "page 2 shown";
  const uint32_t status = soc.read(kVideo + VIDEO_STATUS_Offset).rdata;
  EXPECT_EQ((status & VIDEO_STATUS_PAGE_Msk) >> VIDEO_STATUS_PAGE_Pos, 2u);
  EXPECT_EQ(status & VIDEO_STATUS_UNDERRUN_Msk, 0u);
}

INSTANTIATE_TEST_SUITE_P(Stalls, FabricTest, ::testing::Values(0, 1, 7, 1234),
                         [](const ::testing::TestParamInfo<int>& p) {
                           return p.param == 0 ? std::string("nostall") : "seed" + std::to_string(p.param);
                         });

}  // namespace
