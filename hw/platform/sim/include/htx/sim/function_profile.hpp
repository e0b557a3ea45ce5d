// Where the CPU's clocks went by function (`htx sim --hotspots`): the harness charges every clock to
// an instruction address (PcProfile), and the ELF's function symbols turn those into one line a
// function (FunctionCost).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "htx/sim/elf_image.hpp"

namespace htx::sim {

// Clocks and completed instructions by instruction address, a counter a RAM word, plus one for
// addresses outside RAM (a jump into nowhere still has its clocks counted).
class PcProfile {
 public:
  explicit PcProfile(uint32_t ram_bytes);
  // One clock with the instruction at `pc` in execute; `completed`: it completes in this clock.
  void charge(uint32_t pc, bool completed) {
    const size_t i = pc < ram_bytes_ ? pc / 4 : outside_;
    ++cycles_[i];
    instructions_[i] += completed ? 1u : 0u;
  }
  uint32_t ram_bytes() const { return ram_bytes_; }
  // Index pc / 4 for a RAM address, ram_bytes() / 4 for everything outside RAM.
  std::span<const uint64_t> cycles() const { return cycles_; }
  std::span<const uint64_t> instructions() const { return instructions_; }

 private:
  uint32_t ram_bytes_;
  size_t outside_;
  std::vector<uint64_t> cycles_, instructions_;
};

struct FunctionCost {
  std::string name;      // demangled; "(outside any function)" for the rest
  uint32_t addr = 0;     // where the function starts (0 for the rest)
  uint64_t cycles = 0;
  uint64_t instructions = 0;
};

// The profile by function, the most clocks first (ties by address). A function holds [addr, addr +
// size); one without a size (an assembly label such as _start) holds the addresses up to the next
// function's start or its section's end, whichever is first. An address inside no function (code without a symbol, or outside RAM) goes to
// one last line named "(outside any function)", present only when it has clocks. Functions without
// clocks are left out; of symbols at one address the first with a size names the function; where
// functions overlap, the one starting last holds the address. The cycles add up to the profile's.
std::vector<FunctionCost> cost_by_function(const PcProfile& profile, std::span<const ElfFunction> functions);

// A C++ symbol demangled (the name itself when it is not a mangled C++ name).
std::string demangle(const std::string& name);

}  // namespace htx::sim
