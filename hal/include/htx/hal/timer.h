// Timer driver (hw/regs/timer.json): the 64-bit time counter, one tick per SoC clock.
#pragma once

#include <stdint.h>

#include "htx/hal/regs.h"

namespace htx::hal {

// Reads MTIME as hi, lo, hi and retries when the high word changed in between.
inline uint64_t timer_now() {
  for (;;) {
    const uint32_t hi = HTX_TIMER->MTIME_HI;
    const uint32_t lo = HTX_TIMER->MTIME_LO;
    if (HTX_TIMER->MTIME_HI == hi) return (static_cast<uint64_t>(hi) << 32) | lo;
  }
}

// Whether the counter advances (CTRL.ENABLE, set at reset).
inline bool timer_running() { return (HTX_TIMER->CTRL & TIMER_CTRL_ENABLE_Msk) != 0; }

// Busy-waits until at least `ticks` ticks have passed (each poll is a bus access, so in the host
// simulation time advances with the polling and the loop ends). false at once, without waiting,
// when the counter is stopped (CTRL.ENABLE = 0): the wait would never end.
inline bool timer_wait(uint64_t ticks) {
  if (!timer_running()) return false;
  // Elapsed ticks, not an end time: an end past 2^64 would wrap and end the wait at once.
  const uint64_t start = timer_now();
  while (timer_now() - start < ticks) {
  }
  return true;
}

// Cycles of the CPU (the cycle CSR on the SoC, simulated clocks on the host).
inline uint64_t cpu_cycles() { return backend::cpu_cycles(); }

// Lets at least `cycles` clocks pass without a bus access.
inline void cpu_idle(uint32_t cycles) { backend::idle(cycles); }

}  // namespace htx::hal
