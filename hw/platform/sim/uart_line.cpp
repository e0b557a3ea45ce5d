#include "htx/sim/uart_line.hpp"

#include <stdexcept>

namespace htx::sim {

namespace {

uint32_t checked_cpb(uint32_t clocks_per_bit) {
  if (clocks_per_bit < 4) throw std::invalid_argument("UART: at least 4 clocks per bit are needed");
  return clocks_per_bit;
}

}  // namespace

UartLineDecoder::UartLineDecoder(uint32_t clocks_per_bit) : cpb_(checked_cpb(clocks_per_bit)) {}

void UartLineDecoder::set_clocks_per_bit(uint32_t clocks_per_bit) { cpb_ = checked_cpb(clocks_per_bit); }

std::optional<uint8_t> UartLineDecoder::step(bool line) {
  if (state_ == State::Idle) {
    if (!line) {
      state_ = State::Start;
      wait_ = cpb_ / 2 - 1;  // to the middle of the start bit
    }
    return std::nullopt;
  }
  if (wait_ != 0) {
    --wait_;
    return std::nullopt;
  }
  wait_ = cpb_ - 1;
  switch (state_) {
    case State::Start:
      if (line) {
        state_ = State::Idle;  // a glitch, not a start bit
      } else {
        state_ = State::Data;
        bit_ = 0;
      }
      break;
    case State::Data:
      shift_ = static_cast<uint8_t>((shift_ >> 1) | (line ? 0x80 : 0));
      if (++bit_ == 8) state_ = State::Stop;
      break;
    case State::Stop:
      state_ = State::Idle;
      if (!line) {
        ++framing_errors_;
        return std::nullopt;
      }
      return shift_;
    case State::Idle:
      break;
  }
  return std::nullopt;
}

UartLineEncoder::UartLineEncoder(uint32_t clocks_per_bit) : cpb_(checked_cpb(clocks_per_bit)) {}

void UartLineEncoder::set_clocks_per_bit(uint32_t clocks_per_bit) { cpb_ = checked_cpb(clocks_per_bit); }

bool UartLineEncoder::step() {
  if (bits_left_ == 0) {
    if (queue_.empty()) return true;
    frame_ = static_cast<uint16_t>((1u << 9) | (static_cast<unsigned>(queue_.front()) << 1));
    queue_.pop_front();
    bits_left_ = 10;
    wait_ = cpb_;
  }
  const bool level = frame_ & 1u;
  if (--wait_ == 0) {
    frame_ >>= 1;
    --bits_left_;
    wait_ = cpb_;
  }
  return level;
}

}  // namespace htx::sim
