// The ULX3S board top (hw/platform/ulx3s/htx_ulx3s_top.sv) Verilated as a whole, driven only
// through its pins as the board drives it: the 25 MHz clock, the PWR button and the FTDI serial
// lines. Its RAM starts from the firmware image `htx image` writes (read by $readmemh when the model
// starts, as synthesis reads it into the bitstream), the SoC comes out of reset by itself, and the
// firmware's UART runs at the divisor it computes from SYSCTRL.CLOCK_HZ.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "Vhtx_ulx3s_top.h"
#include "Vhtx_ulx3s_top___024root.h"
#include "board_pins.hpp"
#include "htx/sim/frame_crc.hpp"
#include "htx/sim/video_capture.hpp"
#include "subprocess.hpp"
#include "tmds_reference.hpp"

namespace {

using namespace std::chrono_literals;

struct Ulx3sPins {
  static void clock(Vhtx_ulx3s_top& t, bool level) { t.clk_25mhz = level; }
  static void button(Vhtx_ulx3s_top& t, bool pressed) { t.btn_pwr_n = !pressed; }
  static void host_tx(Vhtx_ulx3s_top& t, bool level) { t.ftdi_txd = level; }
  static bool board_tx(const Vhtx_ulx3s_top& t) { return t.ftdi_rxd != 0; }
};

// The ULX3S with a firmware image in its 128 KiB of RAM, at its 25 MHz.
class Board : public htx::test::BoardPins<Vhtx_ulx3s_top, Ulx3sPins> {
 public:
  explicit Board(const std::string& elf) : BoardPins(elf, 131072, 25'000'000) {}
  // A RAM word, through the model's hierarchy (what a run leaves in memory, seen from outside).
  uint32_t& ram_word(uint32_t addr) {
    return pins().rootp->htx_ulx3s_top__DOT__u_soc__DOT__u_fabric__DOT__u_ram__DOT__mem_q[addr / 4];
  }
};

constexpr uint8_t kLedReset = 1u << 1;

// One frame off the GPDI connector, read as a DVI monitor reads it: the four channels' symbols of
// each pixel clock (the board top's `dvi_symbols`, in front of the DDR serialisers, which only the
// board's build has), the frame found by the vertical sync on the blue channel's control symbols,
// then 640 x 480 data symbols. Every symbol must decode, the channels must agree on what is data,
// and the clock channel must send five ones and five zeros each pixel.
std::vector<uint32_t> capture_screen(Board& board, std::string* problem) {
  using htx::video_test::tmds_decode;
  constexpr uint64_t kLimit = 3 * 800 * 525;
  htx::sim::VideoCapture monitor;
  for (uint64_t i = 0; i < kLimit && monitor.frames() == 0; ++i) {
    board.clock();
    const uint64_t s = board.pins().rootp->htx_ulx3s_top__DOT__dvi_symbols;
    const auto blue = tmds_decode(static_cast<uint16_t>(s & 0x3FF));
    const auto green = tmds_decode(static_cast<uint16_t>((s >> 10) & 0x3FF));
    const auto red = tmds_decode(static_cast<uint16_t>((s >> 20) & 0x3FF));
    if (((s >> 30) & 0x3FF) != 0b0000011111) *problem = "the clock channel sent something else";
    if (blue.de != green.de || blue.de != red.de) *problem = "the channels disagree on the data period";
    // {C1, C0} = {VSYNC, HSYNC} levels in blanking; the sync lines are high in the data period.
    const bool vsync_n = blue.de || (blue.ctrl & 2) != 0;
    monitor.clock(blue.de, vsync_n, (uint32_t{red.data} << 16) | (uint32_t{green.data} << 8) | blue.data);
  }
  return monitor.last_frame();
}

TEST(BoardUlx3s, EchoFirmwareGreetsAtTheBoardsClockAndEchoes) {
  Board board(HTX_FIRMWARE_DIR "/echo.elf");
  EXPECT_TRUE(board.pins().led & kLedReset) << "the SoC is held in reset after configuration";
  // Held 256 clocks (the block RAMs' start after configuration, docs/boards.md).
  for (int i = 0; i < 240; ++i) board.clock();
  EXPECT_TRUE(board.pins().led & kLedReset) << "the power-on reset holds past the block RAMs' start";
  for (int i = 0; i < 32; ++i) board.clock();
  EXPECT_FALSE(board.pins().led & kLedReset) << "the power-on reset ends by itself";

  ASSERT_TRUE(board.run_until("Ctrl-D ends.\r\n", 2'000'000)) << "greeting so far: " << board.received();
  EXPECT_NE(board.received().find("hypertex echo: soc 48545853 at 25000000 Hz"), std::string::npos)
      << board.received();
  board.received().clear();
  board.type("ulx3s!\r");
  ASSERT_TRUE(board.run_until("\r\n", 1'000'000)) << "echo so far: " << board.received();
  EXPECT_EQ(board.received(), "ulx3s!\r\n");
  EXPECT_EQ(board.framing_errors(), 0u);
}

// The PWR button restarts the firmware from its initial state: crt0 copies .data from its load
// image at every start (linker/hypertex.ld), so a warm reset does not run on the values the last run
// left there. Here the last run leaves garbage in every .data word (picolibc's stdout among them).
TEST(BoardUlx3s, ButtonRestartsTheFirmwareFromItsInitialData) {
  Board board(HTX_FIRMWARE_DIR "/echo.elf");
  ASSERT_TRUE(board.run_until("Ctrl-D ends.\r\n", 2'000'000)) << board.received();
  // (Cleared first: the greeting's "hypertex" holds an x, and the typed one would still be on the
  // line when the button is pressed.)
  board.received().clear();
  board.type("x");
  ASSERT_TRUE(board.run_until("x", 1'000'000));
  board.received().clear();
  const auto data_start = board.image().symbol("__data_start");
  const auto data_end = board.image().symbol("__data_copy_end");
  ASSERT_TRUE(data_start && data_end && *data_start < *data_end) << "echo.elf has no .data to check";
  for (uint32_t a = *data_start; a < *data_end; a += 4) board.ram_word(a) = 0xA5A5A5A5u;

  board.press_button(true);
  for (int i = 0; i < 8; ++i) board.clock();
  EXPECT_TRUE(board.pins().led & kLedReset) << "the SoC is in reset while the button is down";
  board.press_button(false);
  ASSERT_TRUE(board.run_until("Ctrl-D ends.\r\n", 2'000'000)) << "after the button: " << board.received();
  EXPECT_EQ(board.received().rfind("hypertex echo: soc 48545853 at 25000000 Hz", 0), 0u) << board.received();
  board.received().clear();
  board.type("again\r");
  ASSERT_TRUE(board.run_until("\r\n", 1'000'000)) << board.received();
  EXPECT_EQ(board.received(), "again\r\n");
}

// The board's main job: the console firmware in the board's RAM draws the cube with the checksum
// the render firmware's cube has on the simulated SoC (`htx sim --json`): soc = board.
TEST(BoardUlx3s, ConsoleDrawsTheFrameOfTheSimulatedSoc) {
  const auto sim = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/render_cube.elf", "--uart", "stdio", "--json"}, 120s);
  ASSERT_EQ(sim.status, 0) << sim.err;
  const size_t key = sim.out.find("\"frame_crc32\":\"");
  ASSERT_NE(key, std::string::npos) << sim.out;
  const std::string sim_crc = sim.out.substr(key + 15, 8);

  Board board(HTX_FIRMWARE_DIR "/console.elf");
  ASSERT_TRUE(board.run_until("htx> ", 20'000'000)) << "boot: " << board.received();
  EXPECT_NE(board.received().find("hypertex console. Type help."), std::string::npos) << board.received();
  board.received().clear();
  board.type("render cube\r");
  ASSERT_TRUE(board.run_until("htx> ", 40'000'000)) << "render: " << board.received();
  EXPECT_NE(board.received().find("fragments 7082"), std::string::npos) << board.received();
  EXPECT_NE(board.received().find(" crc32 " + sim_crc + "\r\n"), std::string::npos)
      << "the simulated SoC's cube is " << sim_crc << "; the board said: " << board.received();
  EXPECT_EQ(board.framing_errors(), 0u);

  // The screen (the console turns the video on at boot) shows the same frame, each pixel 4 x 4.
  std::string problem;
  const std::vector<uint32_t> screen = capture_screen(board, &problem);
  EXPECT_EQ(problem, "");
  ASSERT_EQ(screen.size(), 640u * 480u);
  const std::vector<uint16_t> frame = htx::sim::frame_from_screen(screen, 640, 480, 4);
  ASSERT_EQ(frame.size(), 160u * 120u) << "a 4 x 4 block of the screen is not one colour";
  char crc[9];
  std::snprintf(crc, sizeof crc, "%08x", htx::sim::frame_crc32(frame));
  EXPECT_EQ(std::string(crc), sim_crc) << "the screen's frame against the simulated SoC's";
}

}  // namespace
