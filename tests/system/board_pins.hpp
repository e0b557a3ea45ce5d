// Test support: a Verilated board top driven only through its pins, as the board drives it: its
// clock, its reset button and the serial lines of its USB bridge. The RAM starts from the firmware
// image `htx image` writes: the top's RamInitFile is board_ram.hex in the working directory, which
// the model reads ($readmemh) when it starts, so the constructor writes it into a directory of this
// test's own and starts the model there. Pins describes the top's pin names:
//   static void clock(V&, bool); static void button(V&, bool pressed);
//   static void host_tx(V&, bool level); static bool board_tx(const V&);
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "htx/sim/elf_image.hpp"
#include "htx/sim/uart_line.hpp"
#include "verilated.h"

namespace htx::test {

template <class V, class Pins>
class BoardPins {
 public:
  BoardPins(const std::string& elf, uint32_t ram_bytes, uint32_t clock_hz)
      : from_board_(clocks_per_bit(clock_hz)), to_board_(clocks_per_bit(clock_hz)) {
    dir_ = std::filesystem::temp_directory_path() /
           ("htx_board_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    image_ = sim::load_elf(elf);
    std::ofstream(dir_ / "board_ram.hex") << sim::readmemh_text(sim::ram_words(image_, ram_bytes));
    const auto back = std::filesystem::current_path();
    std::filesystem::current_path(dir_);
    ctx_ = std::make_unique<VerilatedContext>();
    top_ = std::make_unique<V>(ctx_.get(), "board");
    Pins::clock(*top_, false);
    Pins::button(*top_, false);
    Pins::host_tx(*top_, true);
    top_->eval();  // initial blocks: the RAM reads its image here
    std::filesystem::current_path(back);
  }
  ~BoardPins() {
    top_->final();
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  BoardPins(const BoardPins&) = delete;
  BoardPins& operator=(const BoardPins&) = delete;

  // The firmware's UART divisor for 115,200 baud at the board's clock (hal/target/target_init.c).
  static uint32_t clocks_per_bit(uint32_t clock_hz) { return (clock_hz + 115'200 / 2) / 115'200; }

  // One clock: the host's line is set before the rising edge, the board's line sampled after it.
  void clock() {
    Pins::host_tx(*top_, to_board_.step());
    Pins::clock(*top_, true);
    top_->eval();
    Pins::clock(*top_, false);
    top_->eval();
    if (auto byte = from_board_.step(Pins::board_tx(*top_))) received_ += static_cast<char>(*byte);
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
  void press_button(bool pressed) { Pins::button(*top_, pressed); }

  V& pins() { return *top_; }
  const sim::ElfImage& image() const { return image_; }
  std::string& received() { return received_; }
  uint64_t framing_errors() const { return from_board_.framing_errors(); }

 private:
  std::filesystem::path dir_;
  sim::ElfImage image_;
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
  sim::UartLineDecoder from_board_;
  sim::UartLineEncoder to_board_;
  std::string received_;
};

}  // namespace htx::test
