// The ULX3S board top (hw/platform/ulx3s/htx_ulx3s_top.sv) Verilated as a whole, driven only
// through its pins as the board drives it: the 25 MHz clock, the PWR button and the FTDI serial
// lines. Its RAM starts from the firmware image `htx image` writes (read by $readmemh when the model
// starts, as synthesis reads it into the bitstream), the SoC comes out of reset by itself, and the
// firmware's UART runs at the divisor it computes from SYSCTRL.CLOCK_HZ.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "Vhtx_ulx3s_top.h"
#include "Vhtx_ulx3s_top___024root.h"
#include "htx/sim/elf_image.hpp"
#include "htx/sim/uart_line.hpp"
#include "subprocess.hpp"
#include "verilated.h"

namespace {

using namespace std::chrono_literals;

constexpr uint32_t kClockHz = 25'000'000;
constexpr uint32_t kClocksPerBit = (kClockHz + 115'200 / 2) / 115'200;  // as hal/target/target_init.c

// The board with a firmware image: writes the image where the model reads it (board_ram.hex in the
// working directory, a directory of this test's own) and starts the model there.
class Board {
 public:
  explicit Board(const std::string& elf) {
    dir_ = std::filesystem::temp_directory_path() /
           ("htx_board_ulx3s_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    image_ = htx::sim::load_elf(elf);
    const htx::sim::ElfImage& image = image_;
    std::ofstream(dir_ / "board_ram.hex") << htx::sim::readmemh_text(htx::sim::ram_words(image, 131072));
    const auto back = std::filesystem::current_path();
    std::filesystem::current_path(dir_);
    ctx_ = std::make_unique<VerilatedContext>();
    top_ = std::make_unique<Vhtx_ulx3s_top>(ctx_.get(), "board");
    top_->clk_25mhz = 0;
    top_->btn_pwr_n = 1;
    top_->ftdi_txd = 1;
    top_->eval();  // initial blocks: the RAM reads its image here
    std::filesystem::current_path(back);
  }
  ~Board() {
    top_->final();
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }

  // One clock: the host's line and the button are set before the rising edge, the board's line is
  // sampled after it.
  void clock() {
    top_->ftdi_txd = to_board_.step() ? 1 : 0;
    top_->clk_25mhz = 1;
    top_->eval();
    top_->clk_25mhz = 0;
    top_->eval();
    if (auto byte = from_board_.step(top_->ftdi_rxd != 0)) received_ += static_cast<char>(*byte);
    ++cycles_;
  }
  // Runs until `text` has been received (true), or `max_cycles` more clocks have passed (false).
  bool run_until(const std::string& text, uint64_t max_cycles) {
    for (uint64_t i = 0; i < max_cycles; ++i) {
      if (received_.find(text) != std::string::npos) return true;
      clock();
    }
    return received_.find(text) != std::string::npos;
  }
  void type(const std::string& s) {
    for (char c : s) to_board_.push(static_cast<uint8_t>(c));
  }
  void press_button(bool pressed) { top_->btn_pwr_n = pressed ? 0 : 1; }

  Vhtx_ulx3s_top& pins() { return *top_; }
  const htx::sim::ElfImage& image() const { return image_; }
  // A RAM word, through the model's hierarchy (what a run leaves in memory, seen from outside).
  uint32_t& ram_word(uint32_t addr) {
    return top_->rootp->htx_ulx3s_top__DOT__u_soc__DOT__u_fabric__DOT__u_ram__DOT__mem_q[addr / 4];
  }
  std::string& received() { return received_; }
  uint64_t framing_errors() const { return from_board_.framing_errors(); }

 private:
  std::filesystem::path dir_;
  htx::sim::ElfImage image_;
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Vhtx_ulx3s_top> top_;
  htx::sim::UartLineDecoder from_board_{kClocksPerBit};
  htx::sim::UartLineEncoder to_board_{kClocksPerBit};
  std::string received_;
  uint64_t cycles_ = 0;
};

constexpr uint8_t kLedReset = 1u << 1;

TEST(BoardUlx3s, EchoFirmwareGreetsAtTheBoardsClockAndEchoes) {
  Board board(HTX_FIRMWARE_DIR "/echo.elf");
  EXPECT_TRUE(board.pins().led & kLedReset) << "the SoC is held in reset after configuration";
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
}

}  // namespace
