#include "htx/hal/sim/raster_sim_bus.hpp"

#include <cstddef>
#include <cstdio>
#include <stdexcept>

#include "htx_regs.h"

namespace htx::hal::sim {

namespace {

constexpr uint32_t kRegWindow = 0x1000u;
constexpr uint32_t kMemBase = 0x30000000u;   // colour window, then depth window (docs/contracts.md)
constexpr uint32_t kMemBytes = 0x00200000u;

bool in_raster(uint32_t addr) { return addr >= HTX_RASTER_BASE && addr - HTX_RASTER_BASE < kRegWindow; }
bool in_mem(uint32_t addr) { return addr >= kMemBase && addr - kMemBase < kMemBytes; }

[[noreturn]] void fail(const char* what, uint32_t addr) {
  char msg[128];
  std::snprintf(msg, sizeof msg, "raster sim bus: %s at 0x%08X", what, static_cast<unsigned>(addr));
  throw std::runtime_error(msg);
}

}  // namespace

RasterSimBus::RasterSimBus(const std::string& config) : sim_(config) {}

uint32_t RasterSimBus::read(uint32_t addr) {
  if (addr & 3u) fail("unaligned word read", addr);
  if (in_raster(addr)) {
    // A register the unit answers with an error is a load fault on the CPU: here an exception.
    uint32_t data = 0;
    if (sim_.reg_read(addr - HTX_RASTER_BASE, &data)) fail("bus error on register read", addr);
    return data;
  }
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

void RasterSimBus::write(uint32_t addr, uint32_t value) {
  if (addr & 3u) fail("unaligned word write", addr);
  if (in_raster(addr)) {
    if (addr - HTX_RASTER_BASE == offsetof(HTX_RASTER_Type, FIFO)) fifo_words_.push_back(value);
    // A write the unit refuses (the full FIFO while CTRL.ENABLE is 0) is a store fault on the CPU.
    if (sim_.reg_write(addr - HTX_RASTER_BASE, value)) fail("bus error on register write", addr);
    return;
  }
  if (in_mem(addr)) {
    if (sim_.mem_write(addr, value)) fail("bus error on write", addr);
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
