// Area of a flattened Yosys iCE40 netlist by signal scope (see attrib.cpp).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace htx::synth {

using Json = nlohmann::json;

struct Counts {
  long lut4 = 0;
  long carry = 0;
  long ff = 0;
};

// The table of SB_LUT4, SB_CARRY and flip-flops by scope (depth parts below the scopes' common
// prefix), largest first, with a total line: "scope | lut4 | carry | ff" lines. With by_signal,
// one row per signal (its full name below the prefix) instead of per scope.
std::string attribute(const Json& module, const std::string& top, int depth, bool by_signal = false);

}  // namespace htx::synth
