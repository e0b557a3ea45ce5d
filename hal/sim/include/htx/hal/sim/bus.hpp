// The bus the host-simulation HAL talks to: every register or memory access of firmware compiled
// for the host becomes one call here. Implementations: FakeBus (in memory, for driver unit tests)
// and RasterSimBus (the Verilated raster subsystem, one bus transaction per access).
#pragma once

#include <cstdint>

namespace htx::hal::sim {

class SimBus {
 public:
  virtual ~SimBus() = default;
  // One 32-bit access at a byte address (4-aligned). Simulated time advances by the transaction.
  virtual uint32_t read(uint32_t addr) = 0;
  virtual void write(uint32_t addr, uint32_t value) = 0;
  // Lets `cycles` clocks pass without an access (explicit waits of the firmware).
  virtual void wait(uint64_t cycles) = 0;
  // Clocks simulated so far; the firmware's cycle counter in the simulation.
  virtual uint64_t cycles() const = 0;
};

// The bus every access of the current thread goes to. set_bus(nullptr) detaches it; an access
// without a bus throws std::logic_error (a test forgot to attach one).
void set_bus(SimBus* bus);
SimBus& bus();

// Attaches a bus for the lifetime of the object and restores the previous one afterwards.
class ScopedBus {
 public:
  explicit ScopedBus(SimBus& b);
  ~ScopedBus();
  ScopedBus(const ScopedBus&) = delete;
  ScopedBus& operator=(const ScopedBus&) = delete;

 private:
  SimBus* previous_;
};

}  // namespace htx::hal::sim
