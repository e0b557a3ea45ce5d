// htx-synth-attrib: prints where a flattened Yosys iCE40 netlist's area goes (attrib.cpp).
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <string>

#include "attrib.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Area of a flattened Yosys iCE40 netlist by signal scope"};
  std::string netlist_path, top, out_path;
  int depth = 2;
  app.add_option("--netlist", netlist_path, "Yosys JSON netlist (write_json)")->required();
  app.add_option("--top", top, "top module")->required();
  app.add_option("--depth", depth, "scope parts kept below the common prefix")->check(CLI::Range(1, 16));
  bool by_signal = false;
  app.add_flag("--by-signal", by_signal, "one row per signal instead of per scope");
  app.add_option("--out", out_path, "also write the table here");
  CLI11_PARSE(app, argc, argv);

  std::ifstream in(netlist_path);
  if (!in) {
    std::cerr << "htx-synth-attrib: cannot read " << netlist_path << "\n";
    return 1;
  }
  const htx::synth::Json doc = htx::synth::Json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.contains("modules") || !doc["modules"].contains(top)) {
    std::cerr << "htx-synth-attrib: " << netlist_path << " is not a Yosys netlist with module " << top << "\n";
    return 1;
  }
  const htx::synth::Json& module = doc["modules"][top];
  const std::string table = htx::synth::attribute(module, top, depth, by_signal);
  std::cout << table;
  if (!out_path.empty()) {
    std::ofstream out(out_path);
    out << table;
    if (!out) {
      std::cerr << "htx-synth-attrib: cannot write " << out_path << "\n";
      return 1;
    }
  }
  return 0;
}
