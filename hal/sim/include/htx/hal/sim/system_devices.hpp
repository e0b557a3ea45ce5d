// Host models of the SoC's small peripherals for a simulated bus that has no Verilated model of
// them: SYSCTRL (identification, scratch, simulation exit and putchar), UART (bytes out are
// collected at once, bytes in come from a queue) and TIMER (MTIME follows the bus's clock).
// Register layouts are the generated ones (hw/regs).
#pragma once

#include <cstdint>
#include <deque>
#include <string>

#include "htx_regs.h"

namespace htx::hal::sim {

class SystemDevices {
 public:
  // True for addresses in the SYSCTRL, UART and TIMER windows.
  static bool claims(uint32_t addr);
  // `now` is the bus clock (MTIME counts it). Unknown offsets read 0 and ignore writes.
  uint32_t read(uint32_t addr, uint64_t now);
  void write(uint32_t addr, uint32_t value, uint64_t now);

  const std::string& uart_output() const { return uart_out_; }  // UART DATA writes and SIM_PUTCHAR
  void uart_receive(const std::string& bytes) { rx_.insert(rx_.end(), bytes.begin(), bytes.end()); }
  bool exited() const { return exited_; }
  uint32_t exit_code() const { return exit_code_; }

 private:
  // MTIME follows the bus clock while CTRL.ENABLE is set and holds its value while it is clear,
  // as the SoC's timer does.
  bool timer_enabled() const { return (timer_ctrl_ & TIMER_CTRL_ENABLE_Msk) != 0; }
  uint64_t mtime(uint64_t now) const { return timer_enabled() ? now - mtime_offset_ : mtime_held_; }
  void set_mtime(uint64_t value, uint64_t now) {
    mtime_offset_ = now - value;
    mtime_held_ = value;
  }
  std::string uart_out_;
  std::deque<char> rx_;
  uint32_t scratch_ = 0;
  // The registers' reset values (hw/regs): the divisor for 115200 baud at 12 MHz, the timer running.
  uint32_t uart_ctrl_ = (UART_CTRL_DIVISOR_Reset << UART_CTRL_DIVISOR_Pos) | (UART_CTRL_LOOPBACK_Reset << UART_CTRL_LOOPBACK_Pos);
  uint32_t timer_ctrl_ = (TIMER_CTRL_ENABLE_Reset << TIMER_CTRL_ENABLE_Pos) | (TIMER_CTRL_IRQ_ENABLE_Reset << TIMER_CTRL_IRQ_ENABLE_Pos);
  uint64_t mtime_offset_ = 0;
  uint64_t mtime_held_ = 0;  // MTIME while the counter is stopped
  uint64_t mtimecmp_ = ~uint64_t{0};
  bool exited_ = false;
  uint32_t exit_code_ = 0;
};

}  // namespace htx::hal::sim
