// Where the CPU's clocks went by function (`htx sim --hotspots`): the harness charges every clock to
// an instruction address and follows calls and returns (PcProfile), and the ELF's function symbols
// turn those into one line a function (FunctionCost).
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
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

  // Calls and returns, by the RISC-V return-address-stack hints (x1 and x5 are link registers): a
  // JAL or JALR that writes a link register calls, a JALR that jumps through one and does not write
  // one returns. `completed` reports an instruction (its word) completing at `pc`; `live` reports
  // the instruction execute holds in a clock, so that a call's frame opens at the callee's
  // first instruction and a return's closes at the caller's next one (the bubbles between a return
  // and that instruction are the callee's, as its clocks charge them to the return).
  void completed(uint32_t pc, uint32_t word);
  void live(uint32_t pc, uint64_t clock);
  // Closes the frames still open at the end of the run.
  void finish(uint64_t clock);
  // Frames deeper than this are not opened (their calls are still counted, their returns matched):
  // a program that calls and never returns does not grow the harness without bound.
  static constexpr size_t kMaxFrames = 65536;

  struct Entry {
    uint64_t calls = 0;
    uint64_t inclusive = 0;  // clocks from entry to return, the callee's callees included
  };
  // By the address a call went to.
  const std::map<uint32_t, Entry>& entries() const { return entries_; }
  // Call counts by (call site, the address it went to).
  const std::map<std::pair<uint32_t, uint32_t>, uint64_t>& call_sites() const { return call_sites_; }

 private:
  uint32_t ram_bytes_;
  size_t outside_;
  std::vector<uint64_t> cycles_, instructions_;
  struct Frame {
    uint32_t entry;
    uint64_t start;
  };
  std::vector<Frame> stack_;
  std::map<uint32_t, uint32_t> active_;  // frames open by entry: recursion counts the outer one only
  std::map<uint32_t, Entry> entries_;
  std::map<std::pair<uint32_t, uint32_t>, uint64_t> call_sites_;
  uint64_t unframed_ = 0;  // calls past kMaxFrames not yet returned
  bool call_pending_ = false, return_pending_ = false;
  uint32_t call_site_ = 0;
  void close_top(uint64_t clock);
};

struct FunctionCaller {
  std::string name;  // the calling function (or the rest's name)
  uint64_t calls = 0;
};

struct FunctionCost {
  std::string name;     // demangled; "(outside any function)" for the rest
  uint32_t addr = 0;    // where the function starts (0 for the rest)
  uint64_t cycles = 0;  // its own clocks
  uint64_t instructions = 0;
  uint64_t calls = 0;                   // calls that entered it
  uint64_t inclusive = 0;               // clocks from those calls to their returns (0 when never called)
  std::vector<FunctionCaller> callers;  // most calls first
};

// The profile by function, the most clocks first (ties by address). A function holds [addr, addr +
// size); one without a size (an assembly label such as _start) holds the addresses up to the next
// function's start or its section's end, whichever is first. An address inside no function (code
// without a symbol, or outside RAM) goes to one last line named "(outside any function)", present
// only when it has clocks. Functions without clocks are left out; of symbols at one address the
// first with a size names the function; where functions overlap, the one starting last holds the
// address. The cycles add up to the profile's. Calls go to the function holding the address
// called, from the function holding the call site.
std::vector<FunctionCost> cost_by_function(const PcProfile& profile, std::span<const ElfFunction> functions);

// A C++ symbol demangled (the name itself when it is not a mangled C++ name).
std::string demangle(const std::string& name);

}  // namespace htx::sim
