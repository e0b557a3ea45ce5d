// htx regs: where the generated register header, SV packages and reference live in this build.
#include <iostream>

#include "commands.hpp"
#include "htx_paths.h"

namespace htx {

void register_regs(CLI::App& app) {
  auto* cmd = app.add_subcommand("regs", "Show where the generated register header, SV packages and reference are");
  cmd->callback([] {
    std::cout << "C header:     " << HTX_PATH_REGS_HEADER << "\n"
              << "SV packages:  " << HTX_PATH_REGS_SV_DIR << "\n"
              << "reference:    " << HTX_PATH_REGS_DOC << "\n"
              << "source:       " << HTX_PATH_REGS_SOURCE << " (edit these; the build regenerates the rest)\n";
  });
}

}  // namespace htx
