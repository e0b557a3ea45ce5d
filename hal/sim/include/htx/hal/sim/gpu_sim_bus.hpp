// The host-simulation bus over the Verilated GPU (hw/rtl/gpu/sim, GpuSim: raster unit, texture
// unit, framebuffer and depth memories): RASTER and TEXTURE registers are transactions on the GPU's
// register port, the framebuffer, depth and texture memory windows on its memory port, so simulated
// time advances with every access and polling loops end when the hardware goes idle. SYSCTRL, UART
// and TIMER are host models (SystemDevices) whose accesses take one clock. Any other address, and
// any access the GPU answers with an error, throws std::runtime_error naming it (the SoC would
// answer with a bus error).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "htx/hal/sim/bus.hpp"
#include "htx/hal/sim/system_devices.hpp"
#include "htx/rtl/gpu_sim.hpp"

namespace htx::hal::sim {

class GpuSimBus final : public SimBus {
 public:
  // config: a Verilated GPU configuration ("full" or "icebreaker").
  explicit GpuSimBus(const std::string& config);

  uint32_t read(uint32_t addr) override;
  void write(uint32_t addr, uint32_t value) override;
  void wait(uint64_t cycles) override { sim_.idle(cycles); }
  uint64_t cycles() const override { return sim_.cycles(); }

  rtl::GpuSim& gpu() { return sim_; }
  SystemDevices& devices() { return devices_; }
  // Every word written to RASTER.FIFO, in order (what the firmware streamed).
  const std::vector<uint32_t>& fifo_words() const { return fifo_words_; }
  // Words written into the texture memory window.
  uint64_t texture_writes() const { return texture_writes_; }

 private:
  rtl::GpuSim sim_;
  SystemDevices devices_;
  std::vector<uint32_t> fifo_words_;
  uint64_t texture_writes_ = 0;
};

}  // namespace htx::hal::sim
