// htx flash: load a board's bitstream into the FPGA, or into the board's flash: openFPGALoader for
// the ULX3S, iceprog for the iCEBreaker.
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "commands.hpp"

namespace htx {
namespace {

struct FlashArgs {
  std::string bitstream;
  std::string board = "ulx3s";
  bool to_flash = false;  // --flash
  bool to_sram = false;   // --sram
  std::string loader;  // empty: the board's loader from PATH
  bool dry_run = false;
};

// The loader's command line for each board htx builds a bitstream for (docs/boards.md), and the
// Debian package that has it.
struct LoaderCommand {
  std::vector<std::string> argv;
  const char* package;
  bool to_flash;  // the board's flash, else the FPGA until power-off
};
// The bitstream as the loader's argument: a relative path that starts with '-' would be read as
// one of its options.
std::string bitstream_argument(const std::string& path) { return path.rfind('-', 0) == 0 ? "./" + path : path; }

// Whether the bitstream goes to the board's flash: --flash or --sram, else the board's usual way.
// The ULX3S loads the FPGA directly over JTAG; a stock iCEBreaker is programmed through its flash
// (as every iCEBreaker example's `iceprog` does), since loading the FPGA's SRAM over its SPI needs
// the board's SRAM-programming jumpers changed.
bool writes_flash(const FlashArgs& a) {
  if (a.to_flash && a.to_sram) throw std::invalid_argument("--flash and --sram: one or the other");
  if (a.to_flash || a.to_sram) return a.to_flash;
  return a.board == "icebreaker";
}

LoaderCommand loader_command(const FlashArgs& a) {
  const std::string bitstream = bitstream_argument(a.bitstream);
  const bool flash = writes_flash(a);
  if (a.board == "ulx3s") {
    LoaderCommand c{{a.loader.empty() ? "openFPGALoader" : a.loader, "-b", "ulx3s"}, "openfpgaloader", flash};
    if (flash) c.argv.push_back("-f");
    c.argv.push_back(bitstream);
    return c;
  }
  if (a.board == "icebreaker") {  // iceprog writes the flash unless told -S (the FPGA's SRAM)
    LoaderCommand c{{a.loader.empty() ? "iceprog" : a.loader}, "fpga-icestorm", flash};
    if (!flash) c.argv.push_back("-S");
    c.argv.push_back(bitstream);
    return c;
  }
  throw std::runtime_error("no bitstream flow for board " + a.board);
}

int run_flash(const FlashArgs& a) {
  if (!std::filesystem::is_regular_file(a.bitstream))
    throw std::runtime_error(a.bitstream + ": not a file (a bitstream is read from one)");
  if (std::filesystem::file_size(a.bitstream) == 0) throw std::runtime_error(a.bitstream + " is empty");
  const LoaderCommand command = loader_command(a);
  const std::vector<std::string>& argv = command.argv;
  std::string shown;
  for (const std::string& s : argv) shown += (shown.empty() ? "" : " ") + s;
  std::cout << "htx flash: " << shown << "\n" << std::flush;
  if (a.dry_run) return 0;

  const ChildStatus status = run_child(argv);
  if (status.spawn_error != 0) {
    // The advice fits the default loaders only: a --loader program is the user's own.
    const std::string advice =
        a.loader.empty() ? "; install it with: apt-get install " + std::string(command.package) : "";
    throw std::runtime_error("cannot run " + argv[0] + " (" + std::strerror(status.spawn_error) + ")" + advice);
  }
  if (status.succeeded()) {
    std::cout << "htx flash: loaded " << a.bitstream << (command.to_flash ? " into the board's flash" : " into the FPGA")
              << "\n";
    return 0;
  }
  std::cerr << "htx flash: " << argv[0] << " failed (" << status.describe()
            << "); is the board connected, and may this user open its USB device?\n";
  return 1;
}

}  // namespace

void register_flash(CLI::App& app) {
  auto args = std::make_shared<FlashArgs>();
  auto* cmd = app.add_subcommand(
      "flash", "Load a board's bitstream (BUILD/boards/BOARD/...): openFPGALoader for ulx3s, iceprog for icebreaker");
  cmd->add_option("bitstream", args->bitstream, "The bitstream file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--board", args->board, "The board: ulx3s (default) or icebreaker")
      ->check(CLI::IsMember({"ulx3s", "icebreaker"}));
  cmd->add_flag("--flash", args->to_flash,
                "Write the board's SPI flash, so the design loads at every power-on (the iCEBreaker's default)");
  cmd->add_flag("--sram", args->to_sram,
                "Load the FPGA only, until power-off (the ULX3S's default; an iCEBreaker needs its SRAM-programming "
                "jumpers changed for it)");
  cmd->add_option("--loader", args->loader,
                  "The loader program to run (default: openFPGALoader or iceprog, as the board needs, from PATH)");
  cmd->add_flag("--dry-run", args->dry_run, "Print the loader's command line and stop");
  cmd->callback([args]() {
    int status = 1;
    try {
      status = run_flash(*args);
    } catch (const std::exception& e) {
      std::cerr << "htx flash: " << e.what() << "\n";
    }
    std::exit(status_after_output("htx flash", status));
  });
}

}  // namespace htx
