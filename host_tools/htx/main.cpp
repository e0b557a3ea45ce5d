// htx: the one command-line tool for everything a hypertex user does.
#include <exception>
#include <iostream>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "htx_version.h"

int main(int argc, char** argv) {
  CLI::App app{"htx: hypertex, a small open GPU for FPGAs — render, compare, simulate, talk to a board"};
  app.set_version_flag("--version", std::string("htx ") + HTX_VERSION);
  app.require_subcommand(1);
  app.fallthrough();
#define HTX_DECLARE_COMMAND(name) htx::register_##name(app);
#include "htx_commands.inc"
#undef HTX_DECLARE_COMMAND
  htx::require_decimal_integers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RequiredError& e) {
    // A first word that names no subcommand: CLI11 only says one is required.
    if (argc > 1 && argv[1][0] != '-' && app.get_subcommands().empty()) {
      std::cerr << "htx: no command '" << argv[1] << "' (htx --help lists them)\n";
      return 2;
    }
    // An unknown option first (fallthrough leaves it to the subcommand, and there is none).
    if (argc > 1 && argv[1][0] == '-' && app.get_subcommands().empty()) {
      std::cerr << "htx: no option '" << argv[1] << "' before a command (htx --help lists them)\n";
      return 2;
    }
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const CLI::ParseError& e) {
    // --help and --version: status 0. A command line htx cannot take: its message, and status 2
    // for every kind (CLI11's own codes, 105 to 109, would read as a firmware's exit code from
    // htx sim). Every other error is status 1.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::cerr << "htx: " << e.what() << "\n";
    return htx::status_after_output("htx", 1);
  }
  const auto ran = app.get_subcommands();
  return htx::status_after_output(ran.empty() ? "htx" : ("htx " + ran.front()->get_name()).c_str(), 0);
}
