// An in-memory bus for unit tests of HAL drivers and firmware: every word reads back what was last
// written (0 before), scripted read handlers stand in for device behaviour, and every access is
// logged. One clock per access; wait() adds its clocks.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "htx/hal/sim/bus.hpp"

namespace htx::hal::sim {

class FakeBus final : public SimBus {
 public:
  struct Access {
    bool write = false;
    uint32_t addr = 0, value = 0;
    uint64_t cycle = 0;
  };

  uint32_t read(uint32_t addr) override;
  void write(uint32_t addr, uint32_t value) override;
  void wait(uint64_t cycles) override { cycles_ += cycles; }
  uint64_t cycles() const override { return cycles_; }

  // Presets a word (not logged).
  void poke(uint32_t addr, uint32_t value) { mem_[addr] = value; }
  uint32_t peek(uint32_t addr) const;
  // Reads of addr return handler() instead of the stored word.
  void on_read(uint32_t addr, std::function<uint32_t()> handler) { read_handlers_[addr] = std::move(handler); }
  // Writes of addr also call handler(value) after storing it.
  void on_write(uint32_t addr, std::function<void(uint32_t)> handler) { write_handlers_[addr] = std::move(handler); }

  const std::vector<Access>& log() const { return log_; }
  std::vector<uint32_t> writes_to(uint32_t addr) const;
  size_t reads_of(uint32_t addr) const;
  void clear_log() { log_.clear(); }

 private:
  std::map<uint32_t, uint32_t> mem_;
  std::map<uint32_t, std::function<uint32_t()>> read_handlers_;
  std::map<uint32_t, std::function<void(uint32_t)>> write_handlers_;
  std::vector<Access> log_;
  uint64_t cycles_ = 0;
};

}  // namespace htx::hal::sim
