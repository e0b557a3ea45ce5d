// HAL backend `target`: registers are volatile MMIO at their bus addresses (the generated header's
// defaults), memory windows are plain volatile loads and stores, time is the CPU's cycle CSR.
// Freestanding C++17 for rv32im.
#pragma once

#include <stdint.h>

namespace htx::hal::backend {

inline uint32_t mem_read32(uint32_t addr) {
  return *reinterpret_cast<volatile const uint32_t*>(static_cast<uintptr_t>(addr));
}

inline void mem_write32(uint32_t addr, uint32_t value) {
  *reinterpret_cast<volatile uint32_t*>(static_cast<uintptr_t>(addr)) = value;
}

// The 64-bit cycle counter (hi, lo, hi: retried when the low word wrapped between the reads).
inline uint64_t cpu_cycles() {
  uint32_t hi, lo, hi2;
  do {
    asm volatile("rdcycleh %0" : "=r"(hi));
    asm volatile("rdcycle %0" : "=r"(lo));
    asm volatile("rdcycleh %0" : "=r"(hi2));
  } while (hi != hi2);
  return (static_cast<uint64_t>(hi) << 32) | lo;
}

// Lets at least `cycles` clocks pass.
inline void idle(uint32_t cycles) {
  const uint64_t end = cpu_cycles() + cycles;
  while (cpu_cycles() < end) {
  }
}

}  // namespace htx::hal::backend
