// The host end of the SoC's serial line, clock by clock: an 8N1 decoder for the UART's TX pin and
// an 8N1 encoder that drives its RX pin. Both run at a number of clocks per bit, as a serial
// terminal runs at a configured baud rate; the SoC harness sets it to the UART's divisor whenever
// the firmware changes that (set_clocks_per_bit), as a user sets the terminal to the board's rate.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>

namespace htx::sim {

class UartLineDecoder {
 public:
  explicit UartLineDecoder(uint32_t clocks_per_bit);
  // From the next bit on (at least 4; a change inside a frame garbles that frame).
  void set_clocks_per_bit(uint32_t clocks_per_bit);
  uint32_t clocks_per_bit() const { return cpb_; }
  // Samples the line once per clock; returns a byte when its stop bit has been sampled.
  std::optional<uint8_t> step(bool line);
  uint64_t framing_errors() const { return framing_errors_; }

 private:
  enum class State { Idle, Start, Data, Stop };
  uint32_t cpb_;
  State state_ = State::Idle;
  uint32_t wait_ = 0;
  unsigned bit_ = 0;
  uint8_t shift_ = 0;
  uint64_t framing_errors_ = 0;
};

class UartLineEncoder {
 public:
  explicit UartLineEncoder(uint32_t clocks_per_bit);
  // From the next bit on (at least 4).
  void set_clocks_per_bit(uint32_t clocks_per_bit);
  void push(uint8_t byte) { queue_.push_back(byte); }
  // Line level for this clock (idle high); advances one clock.
  bool step();
  bool idle() const { return bits_left_ == 0 && queue_.empty(); }
  size_t queued() const { return queue_.size(); }

 private:
  uint32_t cpb_;
  std::deque<uint8_t> queue_;
  uint16_t frame_ = 0;     // {stop, data, start}, LSB first
  unsigned bits_left_ = 0;
  uint32_t wait_ = 0;
};

}  // namespace htx::sim
