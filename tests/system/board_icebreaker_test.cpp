// The iCEBreaker's bring-up top (hw/platform/icebreaker/htx_icebreaker_top.sv: the CPU, 4 KiB of
// RAM, UART, timer and SYSCTRL, no GPU) Verilated as a whole and driven only through its pins: the
// 12 MHz clock, the user button and the FTDI's serial lines, its RAM from `htx image`'s image.
#include <gtest/gtest.h>

#include <string>

#include "Vhtx_icebreaker_top.h"
#include "board_pins.hpp"

namespace {

struct IcebreakerPins {
  static void clock(Vhtx_icebreaker_top& t, bool level) { t.CLK = level; }
  static void button(Vhtx_icebreaker_top& t, bool pressed) { t.BTN_N = !pressed; }
  static void host_tx(Vhtx_icebreaker_top& t, bool level) { t.RX = level; }
  static bool board_tx(const Vhtx_icebreaker_top& t) { return t.TX != 0; }
};

class Board : public htx::test::BoardPins<Vhtx_icebreaker_top, IcebreakerPins> {
 public:
  explicit Board(const std::string& elf) : BoardPins(elf, 4096, 12'000'000) {}
  bool red_led_lit() { return pins().LEDR_N == 0; }
};

TEST(BoardIcebreaker, BringUpFirmwareGreetsEchoesAndRestartsOnTheButton) {
  Board board(HTX_FIRMWARE_DIR "/bringup.elf");
  EXPECT_TRUE(board.red_led_lit()) << "the SoC is held in reset after configuration";
  // Held 256 clocks (the iCE40's block RAMs read 0 for about 3 us after configuration).
  for (int i = 0; i < 240; ++i) board.clock();
  EXPECT_TRUE(board.red_led_lit()) << "the power-on reset holds past the block RAMs' start";
  for (int i = 0; i < 32; ++i) board.clock();
  EXPECT_FALSE(board.red_led_lit()) << "the power-on reset ends by itself";

  const std::string greeting = "hypertex bring-up: soc 48545853 at 12000000 Hz. Type; it comes back.\r\n";
  ASSERT_TRUE(board.run_until(greeting, 2'000'000)) << "so far: " << board.received();
  EXPECT_EQ(board.received(), greeting);
  board.received().clear();
  board.type("iCE40\r");
  ASSERT_TRUE(board.run_until("\r\n", 1'000'000)) << "echo so far: " << board.received();
  EXPECT_EQ(board.received(), "iCE40\r\n");

  board.received().clear();
  board.press_button(true);
  for (int i = 0; i < 8; ++i) board.clock();
  EXPECT_TRUE(board.red_led_lit()) << "the SoC is in reset while the button is down";
  board.press_button(false);
  ASSERT_TRUE(board.run_until(greeting, 2'000'000)) << "after the button: " << board.received();
  EXPECT_EQ(board.received(), greeting);
  EXPECT_EQ(board.framing_errors(), 0u);
}

// Without the GPU its addresses answer errors, which the CPU takes as access faults: a load from
// RASTER, a store into the framebuffer window, a load from the texture window (mcause 5, 7, 5).
TEST(BoardIcebreaker, GpuAddressesAnswerAccessFaults) {
  Board board(HTX_BOARD_GPU_PROBE_ELF);
  ASSERT_TRUE(board.run_until("E\n", 200'000)) << "so far: " << board.received();
  EXPECT_EQ(board.received(), "575E\n");
}

}  // namespace
