// htx image: a firmware ELF as the RAM initialisation file of a board build ($readmemh).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "htx/model/file_out.hpp"
#include "output_path.hpp"

#if __has_include("htx/sim/elf_image.hpp")
#define HTX_HAVE_ELF_IMAGE 1
#include "htx/sim/elf_image.hpp"
#else
#define HTX_HAVE_ELF_IMAGE 0  // configured with -DHTX_BUILD_RTL=OFF: no SoC harness library
#endif

namespace htx {
namespace {

constexpr uint32_t kResetVector = 0x0000'0000;  // htx_soc's ResetVector (docs/soc.md)

struct ImageArgs {
  std::string elf;
  std::string out;
  uint32_t ram_bytes = 131072;  // the SoC's RAM in simulation and on the ULX3S
};

int run_image(const ImageArgs& a) {
#if HTX_HAVE_ELF_IMAGE
  require_given_path(a.out, "-o");
  require_output_files({&a.out});
  require_not_input(a.out, a.elf);
  const sim::ElfImage elf = sim::load_elf(a.elf);
  // The core starts at its reset vector, not at the ELF's entry point: an image whose entry is
  // elsewhere would run from the wrong place.
  if (elf.entry != kResetVector) {
    char msg[96];
    std::snprintf(msg, sizeof msg, "entry point 0x%08x is not the SoC's reset vector 0x%08x", elf.entry, kResetVector);
    throw std::runtime_error(a.elf + ": " + msg);
  }
  const std::vector<uint32_t> words = sim::ram_words(elf, a.ram_bytes);
  write_file(a.out, sim::readmemh_text(words));
  std::cout << a.out << ": " << words.size() << " words (" << a.ram_bytes << "-byte RAM), entry 0x" << std::hex
            << elf.entry << std::dec << "\n";
  return 0;
#else
  (void)a;
  throw std::runtime_error("this htx was built without the SoC harness (HTX_BUILD_RTL=OFF)");
#endif
}

}  // namespace

void register_image(CLI::App& app) {
  auto args = std::make_shared<ImageArgs>();
  auto* cmd = app.add_subcommand(
      "image", "Write a firmware ELF as a board's RAM initialisation file ($readmemh: a 32-bit word a line)");
  cmd->add_option("elf", args->elf, "Firmware ELF (rv32im), linked for RAM at address 0")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->out, "The .hex file to write")->required();
  cmd->add_option("--ram-bytes", args->ram_bytes, "RAM size in bytes: every word is written (default 131072)")
      ->check(CLI::Range(uint32_t{4}, uint32_t{1} << 28));
  cmd->callback([args]() {
    int status = 1;
    try {
      status = run_image(*args);
    } catch (const std::exception& e) {
      std::cerr << "htx image: " << e.what() << "\n";
    }
    std::exit(status_after_output("htx image", status));
  });
}

}  // namespace htx
