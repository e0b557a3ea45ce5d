#include "htx/sim/function_profile.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>

namespace htx::sim {

PcProfile::PcProfile(uint32_t ram_bytes)
    : ram_bytes_(ram_bytes & ~3u), outside_(ram_bytes_ / 4), cycles_(outside_ + 1), instructions_(outside_ + 1) {}

namespace {
bool is_link(uint32_t reg) {
  return reg == 1 || reg == 5;
}
}  // namespace

void PcProfile::completed(uint32_t pc, uint32_t word) {
  const uint32_t opcode = word & 0x7Fu, rd = (word >> 7) & 0x1Fu, rs1 = (word >> 15) & 0x1Fu;
  bool call = false, ret = false;
  if (opcode == 0x6Fu) {  // JAL
    call = is_link(rd);
  } else if (opcode == 0x67u && ((word >> 12) & 7u) == 0) {  // JALR
    call = is_link(rd);
    ret = is_link(rs1) && (!is_link(rd) || rd != rs1);  // (rd, rs1 both links and different: a coroutine swap)
  }
  if (ret) return_pending_ = true;
  if (call) {
    call_pending_ = true;
    call_site_ = pc;
  }
}

void PcProfile::close_top(uint64_t clock) {
  const Frame f = stack_.back();
  stack_.pop_back();
  if (--active_[f.entry] == 0) entries_[f.entry].inclusive += clock - f.start;  // the outermost frame
}

void PcProfile::live(uint32_t pc, uint64_t clock) {
  if (return_pending_) {
    return_pending_ = false;
    if (unframed_ > 0) {
      --unframed_;
    } else if (!stack_.empty()) {
      close_top(clock);  // (a return above the first call has no frame)
    }
  }
  if (call_pending_) {
    call_pending_ = false;
    ++entries_[pc].calls;
    ++call_sites_[{call_site_, pc}];
    if (stack_.size() < kMaxFrames) {
      stack_.push_back({pc, clock});
      ++active_[pc];
    } else {
      ++unframed_;  // calls that never return (a loop of calls) must not take the host's memory
    }
  }
}

void PcProfile::finish(uint64_t clock) {
  while (!stack_.empty()) close_top(clock);
}

std::string demangle(const std::string& name) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> out(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status), std::free);
  return status == 0 && out ? std::string(out.get()) : name;
}

std::vector<FunctionCost> cost_by_function(const PcProfile& profile, std::span<const ElfFunction> functions) {
  // Start address -> the function starting there and where it ends. Of symbols at one address, the
  // first with a size names it (a label beside a C function).
  struct Extent {
    const ElfFunction* f;
    uint64_t end;
  };
  std::map<uint32_t, Extent> by_start;
  for (const ElfFunction& f : functions) {
    auto [it, added] = by_start.try_emplace(f.addr, Extent{&f, 0});
    if (!added && it->second.f->size == 0 && f.size != 0) it->second.f = &f;
  }
  // A function ends after its size, or, for a symbol without one (an assembly label such as
  // _start), at the next function's start or its section's end, whichever comes first.
  for (auto it = by_start.begin(); it != by_start.end(); ++it) {
    const ElfFunction& f = *it->second.f;
    const auto next = std::next(it);
    uint64_t end = next != by_start.end() ? next->first : uint64_t{f.addr};
    if (f.section_end > f.addr && (next == by_start.end() || f.section_end < end)) end = f.section_end;
    it->second.end = f.size != 0 ? uint64_t{f.addr} + f.size : end;
  }
  std::map<uint32_t, FunctionCost> costs;  // by start address
  FunctionCost rest;
  rest.name = "(outside any function)";
  // The function holding pc (null: none), and its line.
  auto function_at = [&](uint32_t pc) -> const ElfFunction* {
    if (pc >= profile.ram_bytes()) return nullptr;
    const auto it = by_start.upper_bound(pc);  // the function starting last at or before pc
    if (it == by_start.begin()) return nullptr;
    const Extent& candidate = std::prev(it)->second;
    return uint64_t{pc} < candidate.end ? candidate.f : nullptr;
  };
  auto line_of = [&](const ElfFunction* f) -> FunctionCost& {
    if (!f) return rest;
    auto [it, added] = costs.try_emplace(f->addr);
    if (added) {
      it->second.name = demangle(f->name);
      it->second.addr = f->addr;
    }
    return it->second;
  };
  const auto cycles = profile.cycles();
  const auto instructions = profile.instructions();
  for (size_t i = 0; i < cycles.size(); ++i) {
    if (cycles[i] == 0 && instructions[i] == 0) continue;
    const bool in_ram = i + 1 < cycles.size();
    FunctionCost& c = line_of(in_ram ? function_at(static_cast<uint32_t>(i * 4)) : nullptr);
    c.cycles += cycles[i];
    c.instructions += instructions[i];
  }
  for (const auto& [entry, e] : profile.entries()) {
    FunctionCost& c = line_of(function_at(entry));
    c.calls += e.calls;
    c.inclusive += e.inclusive;
  }
  std::map<std::pair<uint32_t, std::string>, uint64_t> edges;  // (callee's start, caller) -> calls
  for (const auto& [site, n] : profile.call_sites()) {
    const ElfFunction* caller = function_at(site.first);
    const ElfFunction* callee = function_at(site.second);
    edges[{callee ? callee->addr : ~0u, caller ? demangle(caller->name) : rest.name}] += n;
  }
  for (const auto& [key, n] : edges) {
    FunctionCost& c = key.first == ~0u ? rest : costs.at(key.first);
    c.callers.push_back({key.second, n});
  }
  std::vector<FunctionCost> out;
  out.reserve(costs.size() + 1);
  for (auto& [addr, c] : costs) out.push_back(std::move(c));
  // The most clocks first, the rest last.
  std::stable_sort(out.begin(), out.end(),
                   [](const FunctionCost& a, const FunctionCost& b) { return a.cycles > b.cycles; });
  if (rest.cycles != 0 || rest.instructions != 0 || rest.calls != 0) out.push_back(std::move(rest));
  for (FunctionCost& c : out) {
    std::stable_sort(c.callers.begin(), c.callers.end(),
                     [](const FunctionCaller& a, const FunctionCaller& b) { return a.calls > b.calls; });
  }
  return out;
}

}  // namespace htx::sim
