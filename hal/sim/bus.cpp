#include "htx/hal/sim/bus.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

#include "htx/hal/sim/reg_proxy.hpp"

namespace htx::hal::sim {

namespace {

thread_local SimBus* g_bus = nullptr;

// The proxies' storage: never read or written, only its addresses matter.
alignas(4) unsigned char g_windows[kPeriphRegionSize];

}  // namespace

void set_bus(SimBus* b) { g_bus = b; }

SimBus& bus() {
  if (!g_bus) throw std::logic_error("hal sim: register or memory access with no SimBus attached (set_bus)");
  return *g_bus;
}

ScopedBus::ScopedBus(SimBus& b) : previous_(g_bus) { g_bus = &b; }
ScopedBus::~ScopedBus() { g_bus = previous_; }

void* window(uint32_t base) {
  if (base < kPeriphRegionBase || base - kPeriphRegionBase >= kPeriphRegionSize || (base & 3u))
  {
    char msg[96];
    std::snprintf(msg, sizeof msg, "hal sim: no register window for base address 0x%08X", static_cast<unsigned>(base));
    throw std::invalid_argument(msg);
  }
  return g_windows + (base - kPeriphRegionBase);
}

uint32_t address_of(const void* proxy) {
  const auto* p = static_cast<const unsigned char*>(proxy);
  if (p < g_windows || p >= g_windows + kPeriphRegionSize)
    throw std::logic_error("hal sim: a register proxy outside the register windows (copied out of a struct?)");
  return kPeriphRegionBase + static_cast<uint32_t>(p - g_windows);
}

}  // namespace htx::hal::sim
