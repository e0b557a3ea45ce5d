// Reads generated SV register packages and writes one CHECK line per constant, in the C header's
// names: the SV side of the header/package agreement test. It parses only `localparam` lines of the
// form the generator writes, and fails loudly on anything else that looks like a constant.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <regex>
#include <string>

namespace {

unsigned long long parse_sv_number(const std::string& s) {
  // 32'h2000_1000, 12'h004, 7
  std::string digits;
  auto tick = s.find('\'');
  if (tick == std::string::npos) return std::stoull(s, nullptr, 10);
  int base = 10;
  switch (s.at(tick + 1)) {
    case 'h': base = 16; break;
    case 'd': base = 10; break;
    case 'b': base = 2; break;
    default: throw std::runtime_error("unsupported literal " + s);
  }
  for (char c : s.substr(tick + 2))
    if (c != '_') digits += c;
  return std::stoull(digits, nullptr, base);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: sv_pkg_checks OUT.inc PKG.sv...\n";
    return 2;
  }
  std::ofstream out(argv[1]);
  const std::regex param(R"(^\s*localparam\s+(?:logic\s*\[\d+:0\]|int unsigned)\s+(\w+)\s*=\s*([0-9'hdb_A-Fa-f]+)\s*;)");
  int checks = 0;
  std::string current_register;  // P_R of the last OFFSET: tells register resets from field resets
  for (int i = 2; i < argc; ++i) {
    std::ifstream in(argv[i]);
    if (!in) {
      std::cerr << "sv_pkg_checks: cannot open " << argv[i] << "\n";
      return 1;
    }
    std::string line;
    while (std::getline(in, line)) {
      std::smatch m;
      if (line.find("localparam") == std::string::npos) continue;
      if (!std::regex_search(line, m, param)) {
        std::cerr << "sv_pkg_checks: unrecognised constant in " << argv[i] << ": " << line << "\n";
        return 1;
      }
      std::string name = m[1];
      const unsigned long long value = parse_sv_number(m[2]);
      // SV name -> the C expression that must equal it.
      auto ends = [&](const std::string& suf) {
        return name.size() > suf.size() && name.compare(name.size() - suf.size(), suf.size(), suf) == 0;
      };
      auto stem = [&](const std::string& suf) { return name.substr(0, name.size() - suf.size()); };
      std::string expr;
      if (ends("_BASE_ADDR")) {
        expr = "HTX_" + stem("_BASE_ADDR") + "_BASE";
        const std::string p = stem("_BASE_ADDR");
        out << "CHECK_EQ_C((uintptr_t)HTX_" << p << ", 0x" << std::hex << value << std::dec << "ull, \"HTX_" << p << "\")\n";
      } else if (ends("_OFFSET")) {
        // P_R_OFFSET: both the #define and the struct member offset must agree.
        expr = stem("_OFFSET") + "_Offset";
        const std::string pr = stem("_OFFSET");
        current_register = pr;
        const auto us = pr.find('_');
        out << "CHECK_EQ_C(offsetof(HTX_" << pr.substr(0, us) << "_Type, " << pr.substr(us + 1) << "), " << value
            << "ull, \"offsetof " << pr << "\")\n";
      } else if (ends("_LSB")) {
        expr = stem("_LSB") + "_Pos";
      } else if (ends("_WIDTH")) {
        expr = stem("_WIDTH") + "_Width";
      } else if (ends("_MASK")) {
        expr = stem("_MASK") + "_Msk";
      } else if (ends("_RESET")) {
        // Register resets are P_R_RESET in both; field resets are in place in SV, unshifted in C.
        const std::string s = stem("_RESET");
        if (s == current_register) {
          expr = name;
        } else {
          expr = "((unsigned long long)" + s + "_Reset << " + s + "_Pos)";
        }
      } else {
        std::cerr << "sv_pkg_checks: unknown constant kind " << name << "\n";
        return 1;
      }
      out << "CHECK_EQ_C(" << expr << ", " << value << "ull, \"" << name << "\")\n";
      ++checks;
    }
  }
  if (checks == 0) {
    std::cerr << "sv_pkg_checks: no constants found\n";
    return 1;
  }
  return out ? 0 : 1;
}
