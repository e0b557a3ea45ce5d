// htx::sim::cost_by_function: each address's clocks go to the function holding it, by its symbol's
// size or, without one, up to the next function; the rest to one "(outside any function)" line.
#include "htx/sim/function_profile.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace {

using htx::sim::cost_by_function;
using htx::sim::ElfFunction;
using htx::sim::FunctionCost;
using htx::sim::PcProfile;

std::map<std::string, FunctionCost> by_name(const std::vector<FunctionCost>& costs) {
  std::map<std::string, FunctionCost> m;
  for (const FunctionCost& c : costs) m[c.name] = c;
  return m;
}

TEST(FunctionProfile, ChargesEachAddressToTheFunctionHoldingIt) {
  PcProfile p(0x1000);
  // _start: a label without a size, up to main at 0x40; main [0x40, 0x60); a gap; leaf [0x80, 0x88).
  const std::vector<ElfFunction> fns = {{"main", 0x40, 0x20}, {"_start", 0x0, 0}, {"leaf", 0x80, 8}};
  for (int i = 0; i < 3; ++i) p.charge(0x3C, true);   // _start's last word
  for (int i = 0; i < 5; ++i) p.charge(0x40, i < 2);  // main's first: 5 clocks, 2 instructions
  p.charge(0x5C, true);                               // main's last word
  p.charge(0x60, true);                               // just past main: the gap
  p.charge(0x84, false);                              // leaf
  p.charge(0x88, true);                               // just past leaf
  p.charge(0x2000, false);                            // outside RAM
  const auto costs = cost_by_function(p, fns);
  ASSERT_EQ(costs.size(), 4u);
  EXPECT_EQ(costs.front().name, "main");                   // the most clocks first
  EXPECT_EQ(costs.back().name, "(outside any function)");  // the rest last
  auto m = by_name(costs);
  EXPECT_EQ(m["main"].cycles, 6u);
  EXPECT_EQ(m["main"].instructions, 3u);
  EXPECT_EQ(m["main"].addr, 0x40u);
  EXPECT_EQ(m["_start"].cycles, 3u);
  EXPECT_EQ(m["leaf"].cycles, 1u);
  EXPECT_EQ(m["leaf"].instructions, 0u);
  EXPECT_EQ(m["(outside any function)"].cycles, 3u);
  EXPECT_EQ(m["(outside any function)"].instructions, 2u);
}

TEST(FunctionProfile, TheSizedSymbolNamesAnAddressAndEmptyFunctionsAreLeftOut) {
  PcProfile p(0x100);
  // A label and a sized function at one address (either order), and a function never run.
  const std::vector<ElfFunction> fns = {
      {"label", 0x10, 0}, {"sized", 0x10, 0x10}, {"idle", 0x40, 4}, {"other", 0x20, 0}};
  p.charge(0x14, true);
  p.charge(0x24, true);  // in "other" (no size: up to idle at 0x40)
  const auto costs = cost_by_function(p, fns);
  ASSERT_EQ(costs.size(), 2u);
  auto m = by_name(costs);
  EXPECT_EQ(m.count("sized"), 1u);
  EXPECT_EQ(m.count("label"), 0u);
  EXPECT_EQ(m.count("idle"), 0u);
  EXPECT_EQ(m["other"].cycles, 1u);
}

TEST(FunctionProfile, ALabelWithoutASizeEndsWithItsSection) {
  PcProfile p(0x100);
  p.charge(0x50, true);
  p.charge(0x5C, true);
  p.charge(0x60, true);  // past the section
  auto costs = cost_by_function(p, std::vector<ElfFunction>{{"entry", 0x50, 0, 0x60}});
  ASSERT_EQ(costs.size(), 2u);
  EXPECT_EQ(costs[0].name, "entry");
  EXPECT_EQ(costs[0].cycles, 2u);
  // The next function first, if it starts before the section's end.
  costs = cost_by_function(p, std::vector<ElfFunction>{{"entry", 0x50, 0, 0x60}, {"next", 0x58, 8, 0x60}});
  EXPECT_EQ(by_name(costs)["entry"].cycles, 1u);
  EXPECT_EQ(by_name(costs)["next"].cycles, 1u);
  // A last label in a section of unknown end holds nothing.
  costs = cost_by_function(p, std::vector<ElfFunction>{{"end_label", 0x50, 0}});
  ASSERT_EQ(costs.size(), 1u);
  EXPECT_EQ(costs[0].name, "(outside any function)");
}

TEST(FunctionProfile, CyclesAddUpAndTiesKeepAddressOrder) {
  PcProfile p(0x400);
  std::vector<ElfFunction> fns;
  for (uint32_t f = 0; f < 8; ++f) fns.push_back({"f" + std::to_string(f), 0x80 * f, 0x80});
  uint64_t total = 0;
  for (uint32_t pc = 0; pc < 0x400; pc += 4) {
    const uint64_t n = (pc / 0x80) % 3;  // f0, f3, f6 none; f1, f4, f7 one a word; the others two
    for (uint64_t k = 0; k < n; ++k) p.charge(pc, true);
    total += n;
  }
  const auto costs = cost_by_function(p, fns);
  uint64_t sum = 0;
  for (const FunctionCost& c : costs) sum += c.cycles;
  EXPECT_EQ(sum, total);
  std::vector<std::string> order;
  for (const FunctionCost& c : costs) order.push_back(c.name);
  EXPECT_EQ(order, (std::vector<std::string>{"f2", "f5", "f1", "f4", "f7"}));
}

uint32_t jal(uint32_t rd) {
  return 0x6Fu | (rd << 7);
}
uint32_t jalr(uint32_t rd, uint32_t rs1) {
  return 0x67u | (rd << 7) | (rs1 << 15);
}

// Feeds a profile as the harness does: each step one clock whose live instruction completes.
struct Trace {
  PcProfile& p;
  uint64_t clock = 0;
  void step(uint32_t pc, uint32_t word) {
    p.live(pc, clock);
    p.charge(pc, true);
    p.completed(pc, word);
    ++clock;
  }
};

// The return-address-stack hints: x1 and x5 link; a call's frame opens at the next live
// instruction, a return's closes there; recursion counts the outer frame only.
TEST(FunctionProfile, CallsAndReturnsByTheLinkRegisterHints) {
  PcProfile p(0x1000);
  Trace t{p};
  auto step = [&t](uint32_t pc, uint32_t word) { t.step(pc, word); };
  step(0x00, jal(1));       // call f (x1)
  step(0x100, jalr(5, 6));  // f calls g through x5 (millicode style)
  step(0x200, jal(0));      // g: a jump (no link), not a call
  step(0x204, jalr(0, 5));  // g returns through x5
  step(0x104, jalr(0, 6));  // f: a jump through x6, not a return
  step(0x108, jal(1));      // f calls f (recursion)
  step(0x100, jalr(1, 5));  // f: rd x1, rs1 x5 differ: returns (closes the inner f) and calls h
  step(0x300, jalr(0, 1));  // h returns
  step(0x10C, jalr(0, 1));  // f returns (the outer f)
  step(0x004, 0x13u);       // back in the caller: a nop
  p.finish(t.clock);
  const auto& e = p.entries();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e.at(0x100).calls, 2u);      // f, twice (the second recursive)
  EXPECT_EQ(e.at(0x100).inclusive, 8u);  // the outer f: clocks 1 to 9
  EXPECT_EQ(e.at(0x200).calls, 1u);      // g
  EXPECT_EQ(e.at(0x200).inclusive, 2u);  // clocks 2 and 3
  EXPECT_EQ(e.at(0x300).calls, 1u);      // h
  EXPECT_EQ(e.at(0x300).inclusive, 1u);
  EXPECT_EQ(p.call_sites().at({0x108, 0x100}), 1u);
  EXPECT_EQ(p.call_sites().at({0x100, 0x300}), 1u);
}

// A recursion deeper than the frames kept: every call counted, the returns matched, so the
// outermost frame still closes at its own return.
TEST(FunctionProfile, CallsBeyondTheFramesKeptStayMatched) {
  PcProfile p(0x1000);
  Trace t{p};
  const size_t depth = PcProfile::kMaxFrames + 10;
  t.step(0x00, jal(1));
  for (size_t i = 0; i < depth - 1; ++i) t.step(0x100, jal(1));  // f calls itself
  t.step(0x100, jalr(0, 1));
  for (size_t i = 0; i < depth - 1; ++i) t.step(0x104, jalr(0, 1));
  const uint64_t returned = t.clock;
  t.step(0x04, 0x13u);
  t.step(0x08, 0x13u);
  p.finish(t.clock);
  EXPECT_EQ(p.entries().at(0x100).calls, depth);
  EXPECT_EQ(p.entries().at(0x100).inclusive, returned - 1);  // from clock 1 to the caller's next
}

TEST(FunctionProfile, CallsGoToTheFunctionsHoldingTheirAddresses) {
  PcProfile p(0x1000);
  Trace t{p};
  auto step = [&t](uint32_t pc, uint32_t word) { t.step(pc, word); };
  step(0x10, jal(1));  // main calls leaf
  step(0x40, 0x13u);
  step(0x44, jalr(0, 1));  // leaf returns
  step(0x14, jal(1));      // main calls leaf again
  step(0x40, jalr(0, 1));
  step(0x18, 0x13u);
  p.finish(t.clock);
  const std::vector<ElfFunction> fns = {{"main", 0x10, 0x20}, {"leaf", 0x40, 0x10}};
  auto m = by_name(cost_by_function(p, fns));
  EXPECT_EQ(m["leaf"].calls, 2u);
  EXPECT_EQ(m["leaf"].inclusive, 3u);
  ASSERT_EQ(m["leaf"].callers.size(), 1u);
  EXPECT_EQ(m["leaf"].callers[0].name, "main");
  EXPECT_EQ(m["leaf"].callers[0].calls, 2u);
  EXPECT_EQ(m["main"].calls, 0u);
  EXPECT_EQ(m["main"].inclusive, 0u);
}

TEST(FunctionProfile, DemanglesCppNamesOnly) {
  EXPECT_EQ(htx::sim::demangle("_ZN3htx5bench5crc32EPKhj"), "htx::bench::crc32(unsigned char const*, unsigned int)");
  EXPECT_EQ(htx::sim::demangle("uart_putc"), "uart_putc");
  EXPECT_EQ(htx::sim::demangle("_Z"), "_Z");
}

}  // namespace
