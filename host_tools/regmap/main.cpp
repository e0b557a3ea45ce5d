// htx-regmap: generates the C header, the SV packages and the register reference from hw/regs.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "regmap.hpp"

namespace fs = std::filesystem;

namespace {

// Writes only when the content changed, so an unchanged map does not rebuild its users.
void write_if_changed(const fs::path& path, const std::string& text) {
  {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      std::stringstream old;
      old << in.rdbuf();
      if (old.str() == text) return;
    }
  }
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw htx::regmap::Error(path.string() + ": cannot write");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"htx-regmap: generate register header, SV packages and docs from hw/regs/*.json"};
  std::vector<std::string> inputs;
  std::string header, sv_dir, doc;
  app.add_option("inputs", inputs, "register map JSON files")->required()->check(CLI::ExistingFile);
  app.add_option("--c-header", header, "C header to write");
  app.add_option("--sv-dir", sv_dir, "directory for the SV packages (htx_<name>_reg_pkg.sv)");
  app.add_option("--doc", doc, "Markdown register reference to write");
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<fs::path> files(inputs.begin(), inputs.end());
    const auto map = htx::regmap::load_map(files);
    if (!header.empty()) {
      std::ostringstream os;
      htx::regmap::emit_c_header(os, map);
      write_if_changed(header, os.str());
    }
    if (!sv_dir.empty()) {
      for (const auto& p : map) {
        std::ostringstream os;
        htx::regmap::emit_sv_package(os, p);
        write_if_changed(fs::path(sv_dir) / (htx::regmap::sv_package_name(p) + ".sv"), os.str());
      }
    }
    if (!doc.empty()) {
      std::ostringstream os;
      htx::regmap::emit_markdown(os, map);
      write_if_changed(doc, os.str());
    }
  } catch (const std::exception& e) {
    std::cerr << "htx-regmap: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
