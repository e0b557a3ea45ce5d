// The HAL drivers over the host backend with the in-memory FakeBus: the same register syntax as on
// the SoC lands on the right bus addresses with the right values, polling loops end, and misuse
// gives clear errors.
#include <gtest/gtest.h>

#include <stdexcept>
#include <type_traits>

#include "htx/hal/framebuffer.h"
#include "htx/hal/video.h"
#include "htx/hal/raster.h"
#include "htx/hal/sim/fake_bus.hpp"
#include "htx/hal/sim/system_devices.hpp"
#include "htx/hal/texture.h"
#include "htx/hal/timer.h"
#include "htx/hal/uart.h"

namespace {

using htx::hal::sim::FakeBus;
using htx::hal::sim::ScopedBus;

constexpr uint32_t kRaster = HTX_RASTER_BASE;

// Read-only registers are const proxies: assigning one does not compile, as with volatile const.
static_assert(!std::is_assignable_v<decltype((HTX_RASTER->STATE)), uint32_t>);
static_assert(std::is_assignable_v<decltype((HTX_RASTER->FIFO)), uint32_t>);
static_assert(sizeof(HTX_RASTER_Type) == RASTER_CNT_DIVFREE_STEPS_Offset + 4);

TEST(HalSim, RegisterSyntaxIsABusTransactionAtBasePlusOffset) {
  FakeBus bus;
  ScopedBus attach(bus);
  HTX_RASTER->FIFO = 0xDEADBEEFu;
  bus.poke(HTX_UART_BASE + UART_STATUS_Offset, 0x5Au);
  const uint32_t status = HTX_UART->STATUS;
  ASSERT_EQ(bus.log().size(), 2u);
  EXPECT_TRUE(bus.log()[0].write);
  EXPECT_EQ(bus.log()[0].addr, kRaster + RASTER_FIFO_Offset);
  EXPECT_EQ(bus.log()[0].value, 0xDEADBEEFu);
  EXPECT_FALSE(bus.log()[1].write);
  EXPECT_EQ(bus.log()[1].addr, HTX_UART_BASE + UART_STATUS_Offset);
  EXPECT_EQ(status, 0x5Au);
  HTX_TIMER->CTRL |= TIMER_CTRL_IRQ_ENABLE_Msk;  // read-modify-write: one read, one write
  EXPECT_EQ(bus.reads_of(HTX_TIMER_BASE + TIMER_CTRL_Offset), 1u);
  EXPECT_EQ(bus.writes_to(HTX_TIMER_BASE + TIMER_CTRL_Offset), std::vector<uint32_t>{TIMER_CTRL_IRQ_ENABLE_Msk});
}

TEST(HalSim, AccessWithoutABusThrows) {
  htx::hal::sim::set_bus(nullptr);
  EXPECT_THROW((void)static_cast<uint32_t>(HTX_RASTER->STATUS), std::logic_error);
  EXPECT_THROW(htx::hal::sim::window(0x10000000u), std::invalid_argument);
}

TEST(HalRaster, PushTriangleWritesStateThenRecordWordsInOrder) {
  FakeBus bus;
  ScopedBus attach(bus);
  uint32_t words[htx::fw::kTriangleWords];
  for (size_t i = 0; i < htx::fw::kTriangleWords; ++i) words[i] = 1000u + static_cast<uint32_t>(i);
  htx::hal::raster_push_triangle(0x00310000u, words);
  const std::vector<uint32_t> fifo = bus.writes_to(kRaster + RASTER_FIFO_Offset);
  ASSERT_EQ(fifo.size(), htx::fw::kTriangleWords + 1);
  EXPECT_EQ(fifo[0], 0x00310000u);
  for (size_t i = 0; i < htx::fw::kTriangleWords; ++i) EXPECT_EQ(fifo[i + 1], words[i]);
}

TEST(HalRaster, ConfigureClearAndCounters) {
  FakeBus bus;
  ScopedBus attach(bus);
  htx::hal::raster_configure(160, 120, 176);
  EXPECT_EQ(bus.peek(kRaster + RASTER_FB_SIZE_Offset), (120u << 16) | 160u);
  EXPECT_EQ(bus.peek(kRaster + RASTER_FB_STRIDE_Offset), 176u);
  htx::hal::raster_clear(true, 0x1234, false, 0xFFFFFFu);
  EXPECT_EQ(bus.peek(kRaster + RASTER_CLEAR_COLOR_Offset), 0x1234u);
  EXPECT_EQ(bus.peek(kRaster + RASTER_CLEAR_DEPTH_Offset), 0xFFFFFFu);
  EXPECT_EQ(bus.peek(kRaster + RASTER_CTRL_Offset), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk);
  bus.poke(kRaster + RASTER_CNT_PIXELS_Offset, 77);
  bus.poke(kRaster + RASTER_CNT_TRIANGLES_Offset, 3);
  htx::hal::RasterCounters c;
  htx::hal::raster_read_counters(&c);
  EXPECT_EQ(c.pixels, 77u);
  EXPECT_EQ(c.triangles, 3u);
  htx::hal::raster_abort();
  EXPECT_EQ(bus.peek(kRaster + RASTER_CTRL_Offset), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_ABORT_Msk);
}

TEST(HalRaster, WaitIdlePollsUntilIdleAndTimesOut) {
  FakeBus bus;
  ScopedBus attach(bus);
  int busy_reads = 5;
  bus.on_read(kRaster + RASTER_STATUS_Offset,
              [&] { return busy_reads-- > 0 ? uint32_t{RASTER_STATUS_BUSY_Msk} : uint32_t{RASTER_STATUS_FIFO_EMPTY_Msk}; });
  EXPECT_TRUE(htx::hal::raster_wait_idle(100));
  EXPECT_EQ(bus.reads_of(kRaster + RASTER_STATUS_Offset), 6u);
  bus.on_read(kRaster + RASTER_STATUS_Offset, [] { return uint32_t{RASTER_STATUS_BUSY_Msk}; });
  EXPECT_FALSE(htx::hal::raster_wait_idle(10));
}

TEST(HalTimer, NowRetriesWhenTheHighWordChangesAndWaitEnds) {
  FakeBus bus;
  ScopedBus attach(bus);
  // The counter wraps its low word between the first two reads.
  int hi_reads = 0;
  bus.on_read(HTX_TIMER_BASE + TIMER_MTIME_HI_Offset, [&] { return hi_reads++ == 0 ? 6u : 7u; });
  bus.on_read(HTX_TIMER_BASE + TIMER_MTIME_LO_Offset, [&] { return hi_reads <= 1 ? 0xFFFFFFFFu : 2u; });
  EXPECT_EQ(htx::hal::timer_now(), (uint64_t{7} << 32) | 2u);

  FakeBus clocked;
  ScopedBus attach2(clocked);
  clocked.on_read(HTX_TIMER_BASE + TIMER_MTIME_LO_Offset, [&] { return static_cast<uint32_t>(clocked.cycles()); });
  clocked.on_read(HTX_TIMER_BASE + TIMER_CTRL_Offset, [] { return 0u; });  // stopped: no wait
  EXPECT_FALSE(htx::hal::timer_wait(50));
  EXPECT_LT(clocked.cycles(), 10u);
  clocked.on_read(HTX_TIMER_BASE + TIMER_CTRL_Offset, [] { return uint32_t{TIMER_CTRL_ENABLE_Msk}; });
  EXPECT_TRUE(htx::hal::timer_wait(50));
  EXPECT_GE(clocked.cycles(), 50u);
  EXPECT_LT(clocked.cycles(), 100u);
  const uint64_t before = htx::hal::cpu_cycles();
  htx::hal::cpu_idle(1000);
  EXPECT_EQ(htx::hal::cpu_cycles() - before, 1000u);

  // A wait that ends past 2^64 counts elapsed ticks: it still waits its 50 (an end time would
  // wrap to a small number and end the wait at once).
  FakeBus near_wrap;
  ScopedBus attach3(near_wrap);
  near_wrap.on_read(HTX_TIMER_BASE + TIMER_CTRL_Offset, [] { return uint32_t{TIMER_CTRL_ENABLE_Msk}; });
  near_wrap.on_read(HTX_TIMER_BASE + TIMER_MTIME_HI_Offset,
                    [&] { return static_cast<uint32_t>((near_wrap.cycles() - 20) >> 32); });
  near_wrap.on_read(HTX_TIMER_BASE + TIMER_MTIME_LO_Offset,
                    [&] { return static_cast<uint32_t>(near_wrap.cycles() - 20); });  // 2^64 - 20 at clock 0
  const uint64_t start = near_wrap.cycles();
  EXPECT_TRUE(htx::hal::timer_wait(50));
  EXPECT_GE(near_wrap.cycles() - start, 50u);
}

// uart_set_divisor writes only a divisor the field holds as it is: 3 would run as 4, 65,536 as 0.
TEST(HalUart, SetDivisorRefusesWhatTheFieldCannotHold) {
  FakeBus bus;
  ScopedBus attach(bus);
  bus.poke(HTX_UART_BASE + UART_CTRL_Offset, 104u);
  EXPECT_FALSE(htx::hal::uart_set_divisor(3));
  EXPECT_FALSE(htx::hal::uart_set_divisor(65536));
  EXPECT_EQ(htx::hal::uart_divisor(), 104u);
  EXPECT_TRUE(htx::hal::uart_set_divisor(4));
  EXPECT_EQ(htx::hal::uart_divisor(), 4u);
  EXPECT_TRUE(htx::hal::uart_set_divisor(65535));
  EXPECT_EQ(htx::hal::uart_divisor(), 65535u);
}

// texture_check against what the unit builds (CAPS), here the board's: 4 slots, the two 16-bit
// formats, 2^10 blocks. A slot past them would point another slot's texture, a texel past the
// memory is a store fault.
TEST(HalTexture, CheckFollowsTheUnitsCapsAndDescriptorsWaitForTheRasterUnit) {
  FakeBus bus;
  ScopedBus attach(bus);
  bus.poke(HTX_TEXTURE_BASE + TEXTURE_CAPS_Offset, (4u << TEXTURE_CAPS_SLOTS_Pos) | (3u << TEXTURE_CAPS_FORMATS_Pos) |
                                                       (10u << TEXTURE_CAPS_BLOCK_BITS_Pos));
  using htx::hal::texture_check;
  EXPECT_EQ(texture_check(3, 0, 5, 5, 0), htx::hal::kTextureOk);
  EXPECT_EQ(texture_check(4, 0, 5, 5, 0), htx::hal::kTextureBadSlot);
  EXPECT_EQ(texture_check(0, 0, 5, 5, 1), htx::hal::kTextureOk);
  EXPECT_EQ(texture_check(0, 0, 5, 5, 2), htx::hal::kTextureBadFormat);  // RGBA8888 not built
  EXPECT_EQ(texture_check(0, 0, 6, 6, 0), htx::hal::kTextureTooLarge);   // 1,366 blocks of 1,024
  const uint32_t chain32 = htx::hal::texture_chain_blocks(5, 5);
  EXPECT_EQ(texture_check(0, 1024 - chain32, 5, 5, 0), htx::hal::kTextureOk);  // ends at the last block
  EXPECT_EQ(texture_check(0, 1025 - chain32, 5, 5, 0), htx::hal::kTextureTooLarge);

  // The raster unit busy (a textured triangle drawing): the descriptor is not written.
  bus.poke(kRaster + RASTER_STATUS_Offset, RASTER_STATUS_BUSY_Msk);
  EXPECT_EQ(htx::hal::texture_set_descriptor(1, 0, 5, 5, 0, 50), htx::hal::kTextureTimeout);
  EXPECT_TRUE(bus.writes_to(HTX_TEXTURE_BASE + TEXTURE_TEX1_Offset).empty());
  bus.poke(kRaster + RASTER_STATUS_Offset, 0);
  EXPECT_EQ(htx::hal::texture_set_descriptor(1, 0, 5, 5, 0, 50), htx::hal::kTextureOk);
  EXPECT_EQ(bus.writes_to(HTX_TEXTURE_BASE + TEXTURE_TEX1_Offset).size(), 1u);
}

TEST(HalUart, PutGetFlush) {
  FakeBus bus;
  ScopedBus attach(bus);
  htx::hal::uart_write("hi");
  EXPECT_EQ(bus.writes_to(HTX_UART_BASE + UART_DATA_Offset), (std::vector<uint32_t>{'h', 'i'}));
  bus.poke(HTX_UART_BASE + UART_DATA_Offset, UART_DATA_RX_EMPTY_Msk);
  uint8_t b = 0;
  EXPECT_FALSE(htx::hal::uart_try_get(&b));
  EXPECT_EQ(htx::hal::uart_get(3), -1);
  bus.poke(HTX_UART_BASE + UART_DATA_Offset, 'x');
  EXPECT_EQ(htx::hal::uart_get(3), 'x');
  EXPECT_FALSE(htx::hal::uart_flush(4));
  bus.poke(HTX_UART_BASE + UART_STATUS_Offset, UART_STATUS_TX_IDLE_Msk);
  EXPECT_TRUE(htx::hal::uart_flush(4));
}

TEST(HalFramebuffer, ReadsPixelsAndRowsFromHalfWords) {
  FakeBus bus;
  ScopedBus attach(bus);
  // stride 5: pixel i at half-word i of the colour window.
  for (uint32_t w = 0; w < 8; ++w) bus.poke(htx::hal::kFbColorBase + 4 * w, ((2 * w + 1) << 16) | (2 * w));
  EXPECT_EQ(htx::hal::fb_read_pixel(5, 2, 1), 7);
  uint16_t row[4] = {};
  htx::hal::fb_read_row(5, 1, 0, 4, row);  // pixels 5..8
  EXPECT_EQ(row[0], 5);
  EXPECT_EQ(row[1], 6);
  EXPECT_EQ(row[2], 7);
  EXPECT_EQ(row[3], 8);
  bus.poke(htx::hal::kFbDepthBase + 4 * 6, 0xABCDEF);
  EXPECT_EQ(htx::hal::fb_read_depth(5, 1, 1), 0xABCDEFu);
}

// Every start parity and length: the pixels in order, nothing written past the n-th (the whole
// words go through a loop of their own, an odd first and an even last pixel apart).
TEST(HalFramebuffer, ReadRowTakesEveryStartAndLength) {
  FakeBus bus;
  ScopedBus attach(bus);
  for (uint32_t w = 0; w < 16; ++w) bus.poke(htx::hal::kFbColorBase + 4 * w, ((2 * w + 1) << 16) | (2 * w));
  for (uint32_t x0 = 0; x0 < 6; ++x0) {
    for (uint32_t n = 0; n <= 8; ++n) {
      uint16_t row[10];
      for (uint16_t& p : row) p = 0xBEEF;
      htx::hal::fb_read_row(16, 1, x0, n, row);  // window pixels 16 + x0 ...
      for (uint32_t k = 0; k < 10; ++k) {
        EXPECT_EQ(row[k], k < n ? 16 + x0 + k : 0xBEEFu) << "x0 " << x0 << " n " << n << " k " << k;
      }
    }
  }
}

// With several colour pages the reads are of the page the raster unit draws into: page p starts
// at pixel p x FB_MEM.PIXELS of the colour window.
TEST(HalFramebuffer, ReadsThePageTheRasterDrawsInto) {
  FakeBus bus;
  ScopedBus attach(bus);
  bus.poke(HTX_RASTER_BASE + RASTER_FB_MEM_Offset, 10u | (3u << RASTER_FB_MEM_PAGES_Pos));
  EXPECT_EQ(htx::hal::fb_pages(), 3u);
  EXPECT_EQ(htx::hal::fb_page_pixels(), 10u);
  for (uint32_t w = 0; w < 15; ++w) bus.poke(htx::hal::kFbColorBase + 4 * w, ((2 * w + 1) << 16) | (2 * w));
  EXPECT_EQ(htx::hal::fb_read_pixel(4, 1, 1), 5);  // page 0
  bus.poke(HTX_RASTER_BASE + RASTER_FB_PAGE_Offset, 1u << RASTER_FB_PAGE_DRAW_Pos);
  EXPECT_EQ(htx::hal::fb_draw_page(), 1u);
  EXPECT_EQ(htx::hal::fb_read_pixel(4, 1, 1), 15);  // pixel 5 of page 1: window pixel 15
  uint16_t row[3] = {};
  htx::hal::fb_read_row(4, 0, 1, 3, row);  // page 1's pixels 1..3: window pixels 11..13
  EXPECT_EQ(row[0], 11);
  EXPECT_EQ(row[1], 12);
  EXPECT_EQ(row[2], 13);
  bus.poke(HTX_RASTER_BASE + RASTER_FB_PAGE_Offset, 2u << RASTER_FB_PAGE_DRAW_Pos);
  EXPECT_EQ(htx::hal::fb_draw_page(), 2u);
  EXPECT_EQ(htx::hal::fb_read_pixel(4, 1, 1), 25);  // pixel 5 of page 2: window pixel 25
  htx::hal::fb_read_row(4, 2, 0, 2, row);  // page 2's pixels 8, 9: window pixels 28, 29
  EXPECT_EQ(row[0], 28);
  EXPECT_EQ(row[1], 29);
  htx::hal::fb_set_draw_page(0);
  htx::hal::fb_set_draw_page(2);
  EXPECT_EQ(bus.writes_to(HTX_RASTER_BASE + RASTER_FB_PAGE_Offset),
            (std::vector<uint32_t>{0u, 2u << RASTER_FB_PAGE_DRAW_Pos}));
}

// The video's page is taken with its enable: each keeps the other when written.
TEST(HalVideo, PageAndEnableKeepEachOther) {
  FakeBus bus;
  ScopedBus attach(bus);
  const uint32_t page2 = 2u << VIDEO_CTRL_PAGE_Pos;
  bus.poke(HTX_VIDEO_BASE + VIDEO_CTRL_Offset, page2);
  htx::hal::video_enable(true);
  EXPECT_EQ(htx::hal::video_requested_page(), 2u);
  bus.poke(HTX_VIDEO_BASE + VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk);
  htx::hal::video_show_page(2);
  EXPECT_EQ(bus.writes_to(HTX_VIDEO_BASE + VIDEO_CTRL_Offset),
            (std::vector<uint32_t>{VIDEO_CTRL_ENABLE_Msk | page2, VIDEO_CTRL_ENABLE_Msk | page2}));
  bus.poke(HTX_VIDEO_BASE + VIDEO_STATUS_Offset, 2u << VIDEO_STATUS_PAGE_Pos);
  EXPECT_EQ(htx::hal::video_shown_page(), 2u);
  bus.poke(HTX_VIDEO_BASE + VIDEO_MODE_Offset, 3u << VIDEO_MODE_PAGES_Pos);
  EXPECT_EQ(htx::hal::video_pages(), 3u);
}

// The control registers start at the hardware's reset values (hw/regs), as the firmware finds them
// on the SoC: the UART at 115200 baud from 12 MHz (divisor 104), no loopback; the timer counting.
TEST(HalSystemDevices, ControlRegistersStartAtTheirResetValues) {
  htx::hal::sim::SystemDevices d;
  const uint32_t uart_ctrl = d.read(HTX_UART_BASE + UART_CTRL_Offset, 0);
  EXPECT_EQ((uart_ctrl & UART_CTRL_DIVISOR_Msk) >> UART_CTRL_DIVISOR_Pos, 104u);
  EXPECT_EQ(uart_ctrl & UART_CTRL_LOOPBACK_Msk, 0u);
  const uint32_t timer_ctrl = d.read(HTX_TIMER_BASE + TIMER_CTRL_Offset, 0);
  EXPECT_NE(timer_ctrl & TIMER_CTRL_ENABLE_Msk, 0u);
  EXPECT_EQ(timer_ctrl & TIMER_CTRL_IRQ_ENABLE_Msk, 0u);
}

// A stopped timer holds its count (CTRL.ENABLE = 0), as the SoC's does, and counts on from it
// when started again; MTIME written while stopped is what it holds.
TEST(HalSystemDevices, AStoppedTimerHoldsItsCount) {
  htx::hal::sim::SystemDevices d;
  const uint32_t mtime = HTX_TIMER_BASE + TIMER_MTIME_LO_Offset, ctrl = HTX_TIMER_BASE + TIMER_CTRL_Offset;
  EXPECT_EQ(d.read(mtime, 100), 100u);
  d.write(ctrl, 0, 100);
  EXPECT_EQ(d.read(mtime, 500), 100u);
  d.write(mtime, 7, 600);
  EXPECT_EQ(d.read(mtime, 700), 7u);
  d.write(ctrl, TIMER_CTRL_ENABLE_Msk, 1000);
  EXPECT_EQ(d.read(mtime, 1010), 17u);
}

TEST(HalSystemDevices, TimerFollowsTheClockUartCollectsBytes) {
  htx::hal::sim::SystemDevices d;
  EXPECT_EQ(d.read(HTX_TIMER_BASE + TIMER_MTIME_LO_Offset, 1234), 1234u);
  d.write(HTX_TIMER_BASE + TIMER_MTIME_LO_Offset, 0, 2000);
  EXPECT_EQ(d.read(HTX_TIMER_BASE + TIMER_MTIME_LO_Offset, 2010), 10u);
  d.write(HTX_UART_BASE + UART_DATA_Offset, 'o', 0);
  d.write(HTX_SYSCTRL_BASE + SYSCTRL_SIM_PUTCHAR_Offset, 'k', 0);
  EXPECT_EQ(d.uart_output(), "ok");
  EXPECT_EQ(d.read(HTX_UART_BASE + UART_DATA_Offset, 0), UART_DATA_RX_EMPTY_Msk);
  d.uart_receive("z");
  EXPECT_TRUE(d.read(HTX_UART_BASE + UART_STATUS_Offset, 0) & UART_STATUS_RX_VALID_Msk);
  EXPECT_EQ(d.read(HTX_UART_BASE + UART_DATA_Offset, 0), uint32_t{'z'});
  EXPECT_EQ(d.read(HTX_SYSCTRL_BASE + SYSCTRL_ID_Offset, 0), SYSCTRL_ID_RESET);
  d.write(HTX_SYSCTRL_BASE + SYSCTRL_SIM_EXIT_Offset, 3, 0);
  EXPECT_TRUE(d.exited());
  EXPECT_EQ(d.exit_code(), 3u);
}

}  // namespace
