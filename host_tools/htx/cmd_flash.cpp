// htx flash: load a board's bitstream with openFPGALoader (into the FPGA, or into the board's flash).
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"

extern char** environ;

namespace htx {
namespace {

struct FlashArgs {
  std::string bitstream;
  std::string board = "ulx3s";
  bool to_flash = false;
  std::string loader = "openFPGALoader";
  bool dry_run = false;
};

// openFPGALoader's name for each board htx builds a bitstream for (docs/boards.md).
std::string loader_board(const std::string& board) {
  if (board == "ulx3s") return "ulx3s";
  throw std::runtime_error("no bitstream flow for board " + board);
}

int run_flash(const FlashArgs& a) {
  if (std::filesystem::file_size(a.bitstream) == 0) throw std::runtime_error(a.bitstream + " is empty");
  std::vector<std::string> argv = {a.loader, "-b", loader_board(a.board)};
  if (a.to_flash) argv.push_back("-f");
  argv.push_back(a.bitstream);
  std::string shown;
  for (const std::string& s : argv) shown += (shown.empty() ? "" : " ") + s;
  std::cout << "htx flash: " << shown << "\n" << std::flush;
  if (a.dry_run) return 0;

  std::vector<char*> cargv;
  for (const std::string& s : argv) cargv.push_back(const_cast<char*>(s.c_str()));
  cargv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, a.loader.c_str(), nullptr, nullptr, cargv.data(), environ);
  if (rc != 0) {
    throw std::runtime_error("cannot run " + a.loader + " (" + std::strerror(rc) +
                             "); install it with: apt-get install openfpgaloader");
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("waiting for the loader: ") + std::strerror(errno));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    std::cout << "htx flash: loaded " << a.bitstream << (a.to_flash ? " into the board's flash" : " into the FPGA")
              << "\n";
    return 0;
  }
  std::cerr << "htx flash: " << a.loader << " failed ("
            << (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status)) : std::string("killed"))
            << "); is the board connected, and may this user open its USB device?\n";
  return 1;
}

}  // namespace

void register_flash(CLI::App& app) {
  auto args = std::make_shared<FlashArgs>();
  auto* cmd = app.add_subcommand(
      "flash", "Load a board's bitstream (BUILD/boards/ulx3s/htx_ulx3s.bit) with openFPGALoader");
  cmd->add_option("bitstream", args->bitstream, "The bitstream file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--board", args->board, "The board (default ulx3s)")->check(CLI::IsMember({"ulx3s"}));
  cmd->add_flag("--flash", args->to_flash,
                "Write the board's SPI flash, so the design loads at every power-on (default: the FPGA only, "
                "until power-off)");
  cmd->add_option("--loader", args->loader, "The openFPGALoader program to run (default: openFPGALoader from PATH)");
  cmd->add_flag("--dry-run", args->dry_run, "Print the loader's command line and stop");
  cmd->callback([args]() {
    int status = 1;
    try {
      status = run_flash(*args);
    } catch (const std::exception& e) {
      std::cerr << "htx flash: " << e.what() << "\n";
    }
    std::exit(status);
  });
}

}  // namespace htx
