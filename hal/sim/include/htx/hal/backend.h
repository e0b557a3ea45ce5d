// HAL backend `sim`: firmware compiled for the host. The generated register structs are built from
// register proxies (reg_proxy.hpp) and each peripheral's block is a host-side window of them;
// memory windows and waits go to the current SimBus.
#pragma once

#include <cstdint>

#include "htx/hal/sim/bus.hpp"
#include "htx/hal/sim/reg_proxy.hpp"

#define __IM const
#define __OM
#define __IOM
#define HTX_REG_WORD ::htx::hal::sim::RegProxy
#define HTX_PERIPH_ADDR(base) (::htx::hal::sim::window(base))

namespace htx::hal::backend {

inline uint32_t mem_read32(uint32_t addr) { return sim::bus().read(addr); }
inline void mem_write32(uint32_t addr, uint32_t value) { sim::bus().write(addr, value); }
inline uint64_t cpu_cycles() { return sim::bus().cycles(); }
inline void idle(uint32_t cycles) { sim::bus().wait(cycles); }

}  // namespace htx::hal::backend
