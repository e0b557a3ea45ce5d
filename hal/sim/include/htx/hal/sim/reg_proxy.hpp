// Register proxies: the host simulation's register word. The generated register structs are laid
// over a host-side window of these (one 4 KiB window per peripheral slot), so a member's position
// in the window is its offset from the peripheral base; reading or assigning one performs a bus
// transaction at that bus address. Read-only registers are `const` proxies, so writing one does not
// compile, exactly as with the target's `volatile const`.
#pragma once

#include <cstdint>

#include "htx/hal/sim/bus.hpp"

namespace htx::hal::sim {

// Start of the peripheral region the windows cover (16 slots of 4 KiB, docs/contracts.md).
inline constexpr uint32_t kPeriphRegionBase = 0x20000000u;
inline constexpr uint32_t kPeriphRegionSize = 0x10000u;

// The window standing for the register block at bus address `base` (inside the peripheral region;
// anything else throws std::invalid_argument).
void* window(uint32_t base);
// The bus address a proxy inside the windows stands for.
uint32_t address_of(const void* proxy);

class RegProxy {
 public:
  RegProxy() = default;
  RegProxy(const RegProxy&) = delete;  // `auto r = HTX_X->R;` would copy a proxy, not read a value

  operator uint32_t() const { return bus().read(address_of(this)); }
  RegProxy& operator=(uint32_t value) {
    bus().write(address_of(this), value);
    return *this;
  }
  RegProxy& operator=(const RegProxy& other) { return *this = static_cast<uint32_t>(other); }
  RegProxy& operator|=(uint32_t v) { return *this = static_cast<uint32_t>(*this) | v; }
  RegProxy& operator&=(uint32_t v) { return *this = static_cast<uint32_t>(*this) & v; }
  RegProxy& operator^=(uint32_t v) { return *this = static_cast<uint32_t>(*this) ^ v; }

 private:
  uint32_t never_accessed_ = 0;  // gives the proxy the size of a register word
};

static_assert(sizeof(RegProxy) == 4, "a proxy must occupy exactly one register word");

}  // namespace htx::hal::sim
