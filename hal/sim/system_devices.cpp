#include "htx/hal/sim/system_devices.hpp"

#include "htx_regs.h"

namespace htx::hal::sim {

namespace {

constexpr uint32_t kWindow = 0x1000u;

bool in(uint32_t addr, uint32_t base) { return addr >= base && addr - base < kWindow; }

}  // namespace

bool SystemDevices::claims(uint32_t addr) {
  return in(addr, HTX_SYSCTRL_BASE) || in(addr, HTX_UART_BASE) || in(addr, HTX_TIMER_BASE);
}

uint32_t SystemDevices::read(uint32_t addr, uint64_t now) {
  if (in(addr, HTX_SYSCTRL_BASE)) {
    switch (addr - HTX_SYSCTRL_BASE) {
      case SYSCTRL_ID_Offset: return SYSCTRL_ID_RESET;
      case SYSCTRL_VERSION_Offset: return SYSCTRL_VERSION_RESET;
      case SYSCTRL_CLOCK_HZ_Offset: return SYSCTRL_CLOCK_HZ_RESET;
      case SYSCTRL_SCRATCH_Offset: return scratch_;
      case SYSCTRL_PLATFORM_Offset: return SYSCTRL_PLATFORM_SIM_Msk;
      default: return 0;
    }
  }
  if (in(addr, HTX_UART_BASE)) {
    switch (addr - HTX_UART_BASE) {
      case UART_DATA_Offset: {
        if (rx_.empty()) return UART_DATA_RX_EMPTY_Msk;
        const uint32_t b = static_cast<unsigned char>(rx_.front());
        rx_.pop_front();
        return b;
      }
      // Bytes leave at once: the transmitter is always empty and idle.
      case UART_STATUS_Offset:
        return UART_STATUS_TX_EMPTY_Msk | UART_STATUS_TX_IDLE_Msk | (rx_.empty() ? 0u : UART_STATUS_RX_VALID_Msk);
      case UART_CTRL_Offset: return uart_ctrl_;
      case UART_LEVEL_Offset:
        return (static_cast<uint32_t>(rx_.size() > 16 ? 16 : rx_.size()) << UART_LEVEL_RX_Pos) & UART_LEVEL_RX_Msk;
      default: return 0;
    }
  }
  if (in(addr, HTX_TIMER_BASE)) {
    switch (addr - HTX_TIMER_BASE) {
      case TIMER_MTIME_LO_Offset: return static_cast<uint32_t>(mtime(now));
      case TIMER_MTIME_HI_Offset: return static_cast<uint32_t>(mtime(now) >> 32);
      case TIMER_MTIMECMP_LO_Offset: return static_cast<uint32_t>(mtimecmp_);
      case TIMER_MTIMECMP_HI_Offset: return static_cast<uint32_t>(mtimecmp_ >> 32);
      case TIMER_CTRL_Offset: return timer_ctrl_;
      case TIMER_STATUS_Offset: return mtime(now) >= mtimecmp_ ? TIMER_STATUS_MATCH_Msk : 0u;
      default: return 0;
    }
  }
  return 0;
}

void SystemDevices::write(uint32_t addr, uint32_t value, uint64_t now) {
  if (in(addr, HTX_SYSCTRL_BASE)) {
    switch (addr - HTX_SYSCTRL_BASE) {
      case SYSCTRL_SCRATCH_Offset: scratch_ = value; break;
      case SYSCTRL_SIM_EXIT_Offset:
        exited_ = true;
        exit_code_ = (value & SYSCTRL_SIM_EXIT_CODE_Msk) >> SYSCTRL_SIM_EXIT_CODE_Pos;
        break;
      case SYSCTRL_SIM_PUTCHAR_Offset: uart_out_.push_back(static_cast<char>(value & 0xFFu)); break;
      default: break;
    }
    return;
  }
  if (in(addr, HTX_UART_BASE)) {
    if (addr - HTX_UART_BASE == UART_DATA_Offset) uart_out_.push_back(static_cast<char>(value & 0xFFu));
    if (addr - HTX_UART_BASE == UART_CTRL_Offset) uart_ctrl_ = value;
    return;
  }
  if (in(addr, HTX_TIMER_BASE)) {
    const uint64_t t = mtime(now);
    switch (addr - HTX_TIMER_BASE) {
      case TIMER_MTIME_LO_Offset: set_mtime((t & ~uint64_t{0xFFFFFFFFu}) | value, now); break;
      case TIMER_MTIME_HI_Offset: set_mtime((t & 0xFFFFFFFFu) | (uint64_t{value} << 32), now); break;
      case TIMER_MTIMECMP_LO_Offset: mtimecmp_ = (mtimecmp_ & ~uint64_t{0xFFFFFFFFu}) | value; break;
      case TIMER_MTIMECMP_HI_Offset: mtimecmp_ = (mtimecmp_ & 0xFFFFFFFFu) | (uint64_t{value} << 32); break;
      case TIMER_CTRL_Offset:
        timer_ctrl_ = value;
        set_mtime(t, now);  // a stopped counter holds its value, a started one counts on from it
        break;
      default: break;
    }
  }
}

}  // namespace htx::hal::sim
