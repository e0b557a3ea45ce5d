#include "htx/hal/sim/gpu_sim_bus.hpp"

#include <cstddef>
#include <cstdio>
#include <stdexcept>

#include "htx_regs.h"

namespace htx::hal::sim {

namespace {

constexpr uint32_t kRegWindow = 0x1000u;
constexpr uint32_t kFbBase = 0x30000000u;  // colour window, then depth window (docs/contracts.md)
constexpr uint32_t kFbBytes = 0x00200000u;
constexpr uint32_t kTexBase = 0x40000000u;  // texture memory window
constexpr uint32_t kTexBytes = 0x00100000u;

bool in(uint32_t addr, uint32_t base, uint32_t size) { return addr >= base && addr - base < size; }
bool in_regs(uint32_t addr) {
  return in(addr, HTX_RASTER_BASE, kRegWindow) || in(addr, HTX_TEXTURE_BASE, kRegWindow);
}
bool in_mem(uint32_t addr) { return in(addr, kFbBase, kFbBytes) || in(addr, kTexBase, kTexBytes); }

[[noreturn]] void fail(const char* what, uint32_t addr) {
  char msg[128];
  std::snprintf(msg, sizeof msg, "gpu sim bus: %s at 0x%08X", what, static_cast<unsigned>(addr));
  throw std::runtime_error(msg);
}

}  // namespace

GpuSimBus::GpuSimBus(const std::string& config) : sim_(config) {}

uint32_t GpuSimBus::read(uint32_t addr) {
  if (addr & 3u) fail("unaligned word read", addr);
  if (in_regs(addr)) return sim_.read_reg(addr);
  if (in_mem(addr)) {
    uint32_t data = 0;
    if (sim_.mem_read(addr, &data)) fail("bus error on read", addr);
    return data;
  }
  if (SystemDevices::claims(addr)) {
    sim_.idle(1);
    return devices_.read(addr, sim_.cycles());
  }
  fail("no device for read", addr);
}

void GpuSimBus::write(uint32_t addr, uint32_t value) {
  if (addr & 3u) fail("unaligned word write", addr);
  if (in_regs(addr)) {
    if (addr == HTX_RASTER_BASE + offsetof(HTX_RASTER_Type, FIFO)) fifo_words_.push_back(value);
    sim_.write_reg(addr, value);
    return;
  }
  if (in_mem(addr)) {
    if (sim_.mem_write(addr, value)) fail("bus error on write", addr);
    texture_writes_ += in(addr, kTexBase, kTexBytes) ? 1 : 0;
    return;
  }
  if (SystemDevices::claims(addr)) {
    sim_.idle(1);
    devices_.write(addr, value, sim_.cycles());
    return;
  }
  fail("no device for write", addr);
}

}  // namespace htx::hal::sim
