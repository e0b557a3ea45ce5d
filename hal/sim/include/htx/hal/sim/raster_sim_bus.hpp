// The host-simulation bus over the Verilated raster subsystem (hw/rtl/raster/sim, RasterSim):
// RASTER registers and the framebuffer/depth windows are real bus transactions on the Verilated
// model, so simulated time advances with every access and a polling loop ends when the hardware
// goes idle; SYSCTRL, UART and TIMER are host models (SystemDevices) whose accesses take one clock.
// Any other address throws std::runtime_error naming it (the SoC would answer with a bus error).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "htx/hal/sim/bus.hpp"
#include "htx/hal/sim/system_devices.hpp"
#include "htx/rtl/raster_sim.hpp"

namespace htx::hal::sim {

class RasterSimBus final : public SimBus {
 public:
  // config: a Verilated raster configuration ("full" or "icebreaker").
  explicit RasterSimBus(const std::string& config);

  uint32_t read(uint32_t addr) override;
  void write(uint32_t addr, uint32_t value) override;
  void wait(uint64_t cycles) override { sim_.idle(cycles); }
  uint64_t cycles() const override { return sim_.cycles(); }

  rtl::RasterSim& raster() { return sim_; }
  SystemDevices& devices() { return devices_; }
  // Every word written to RASTER.FIFO, in order (what the firmware streamed).
  const std::vector<uint32_t>& fifo_words() const { return fifo_words_; }

 private:
  rtl::RasterSim sim_;
  SystemDevices devices_;
  std::vector<uint32_t> fifo_words_;
};

}  // namespace htx::hal::sim
