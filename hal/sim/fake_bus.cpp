#include "htx/hal/sim/fake_bus.hpp"

#include <cstdio>
#include <stdexcept>

namespace htx::hal::sim {

namespace {

void check_aligned(uint32_t addr) {
  if (addr & 3u) {
    char msg[80];
    std::snprintf(msg, sizeof msg, "fake bus: unaligned word access at 0x%08X", static_cast<unsigned>(addr));
    throw std::invalid_argument(msg);
  }
}

}  // namespace

uint32_t FakeBus::read(uint32_t addr) {
  check_aligned(addr);
  ++cycles_;
  const auto h = read_handlers_.find(addr);
  const uint32_t v = h != read_handlers_.end() ? h->second() : peek(addr);
  log_.push_back({false, addr, v, cycles_});
  return v;
}

void FakeBus::write(uint32_t addr, uint32_t value) {
  check_aligned(addr);
  ++cycles_;
  mem_[addr] = value;
  log_.push_back({true, addr, value, cycles_});
  const auto h = write_handlers_.find(addr);
  if (h != write_handlers_.end()) h->second(value);
}

uint32_t FakeBus::peek(uint32_t addr) const {
  const auto it = mem_.find(addr);
  return it == mem_.end() ? 0u : it->second;
}

std::vector<uint32_t> FakeBus::writes_to(uint32_t addr) const {
  std::vector<uint32_t> out;
  for (const Access& a : log_)
    if (a.write && a.addr == addr) out.push_back(a.value);
  return out;
}

size_t FakeBus::reads_of(uint32_t addr) const {
  size_t n = 0;
  for (const Access& a : log_) n += !a.write && a.addr == addr;
  return n;
}

}  // namespace htx::hal::sim
