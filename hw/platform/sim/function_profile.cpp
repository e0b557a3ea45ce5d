#include "htx/sim/function_profile.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>

namespace htx::sim {

PcProfile::PcProfile(uint32_t ram_bytes)
    : ram_bytes_(ram_bytes & ~3u), outside_(ram_bytes_ / 4), cycles_(outside_ + 1), instructions_(outside_ + 1) {}

std::string demangle(const std::string& name) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> out(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status),
                                             std::free);
  return status == 0 && out ? std::string(out.get()) : name;
}

std::vector<FunctionCost> cost_by_function(const PcProfile& profile, std::span<const ElfFunction> functions) {
  // Start address -> the function starting there (the first symbol wins over its aliases).
  std::map<uint32_t, const ElfFunction*> by_start;
  for (const ElfFunction& f : functions) {
    // Of symbols at one address, the first with a size names it (a label beside a C function).
    auto [it, added] = by_start.emplace(f.addr, &f);
    if (!added && it->second->size == 0 && f.size != 0) it->second = &f;
  }
  // Where each function ends: its size, or for a symbol without one (an assembly label such as
  // _start) the next function's start or its section's end, whichever comes first.
  std::map<uint32_t, uint64_t> end_of;
  for (auto it = by_start.begin(); it != by_start.end(); ++it) {
    const ElfFunction& f = *it->second;
    if (f.size != 0) {
      end_of[f.addr] = uint64_t{f.addr} + f.size;
      continue;
    }
    const auto next = std::next(it);
    uint64_t end = next != by_start.end() ? next->first : uint64_t{f.addr};
    if (f.section_end > f.addr && (next == by_start.end() || f.section_end < end)) end = f.section_end;
    end_of[f.addr] = end;
  }
  std::map<uint32_t, FunctionCost> costs;  // by start address
  FunctionCost rest{"(outside any function)", 0, 0, 0};
  const auto cycles = profile.cycles();
  const auto instructions = profile.instructions();
  for (size_t i = 0; i < cycles.size(); ++i) {
    if (cycles[i] == 0 && instructions[i] == 0) continue;
    const bool in_ram = i + 1 < cycles.size();
    const uint32_t pc = static_cast<uint32_t>(i * 4);
    // The function starting last at or before pc, if pc is inside it.
    auto it = in_ram ? by_start.upper_bound(pc) : by_start.begin();
    const ElfFunction* f = nullptr;
    if (in_ram && it != by_start.begin()) {
      const ElfFunction* candidate = std::prev(it)->second;
      if (uint64_t{pc} < end_of[candidate->addr]) f = candidate;
    }
    FunctionCost& c = f ? costs.try_emplace(f->addr, FunctionCost{demangle(f->name), f->addr, 0, 0}).first->second
                        : rest;
    c.cycles += cycles[i];
    c.instructions += instructions[i];
  }
  std::vector<FunctionCost> out;
  out.reserve(costs.size() + 1);
  for (auto& [addr, c] : costs) out.push_back(std::move(c));
  std::stable_sort(out.begin(), out.end(),
                   [](const FunctionCost& a, const FunctionCost& b) { return a.cycles > b.cycles; });
  if (rest.cycles != 0 || rest.instructions != 0) out.push_back(std::move(rest));
  return out;
}

}  // namespace htx::sim
