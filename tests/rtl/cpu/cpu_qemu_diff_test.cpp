// Differential test of htx_cpu against QEMU's RV32IM (qemu-riscv32, Linux user mode, from Debian's
// qemu-user): seeded random programs (random_program.hpp) run on both, and the signature each
// leaves (registers, data region, checkpoints, result log) must agree word for word, with the
// core's buses answering at once and with random wait states. QEMU is the reference because it is
// an implementation of the ISA that shares nothing with this project's; the instruction tests
// (tests/rtl/isa) check the edge cases one by one, this test the instructions in the orders,
// hazards and timings that programs and the buses produce.
//
// A failing program's source and ELFs stay in the build directory (random_programs/seed_N.*);
// the message names the seed and the first differing word.
//
// Each of the kCases cases runs 16 programs, seeds 1 to 128 in all; the first two of each also run
// on the whole SoC (`htx sim --elf ... --signature ... --stall-seed`), its fabric and RAM between
// the core and memory. A longer run over other seeds (not a CTest run: the tests stay quick) sets
// the environment:
//   HTX_CPU_DIFF_FIRST_SEED=N      the first seed (default 1)
//   HTX_CPU_DIFF_PER_CASE=N        programs in each case (default 16)
//   HTX_CPU_DIFF_ON_SOC=N          of which the first N also run on the SoC (default 2)

#include <gtest/gtest.h>

#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "random_program.hpp"
#include "subprocess.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using htx::cpu_tb::kRandomProgramSignatureWords;
using htx::test::run_program;
using htx::test::RunResult;

constexpr int kCases = 8;
// Every program executes at least this many instructions (the generator's loops and calls make
// most run some thousands); fewer would mean the body was skipped.
constexpr uint64_t kLeastInstructions = 400;

struct ProgramFiles {
  fs::path source, core_elf, qemu_elf;
};

ProgramFiles files_for(uint64_t seed) {
  const fs::path dir = HTX_RANDOM_PROGRAM_DIR;
  fs::create_directories(dir);
  const std::string stem = "seed_" + std::to_string(seed);
  return {dir / (stem + ".S"), dir / (stem + ".core.elf"), dir / (stem + ".qemu.elf")};
}

// A command for messages: its arguments joined by spaces.
std::string command_line(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& a : argv) text += (text.empty() ? "" : " ") + a;
  return text;
}

// Empty on success, else the compiler's message.
std::string compile(const fs::path& source, const fs::path& elf, bool for_qemu) {
  std::vector<std::string> argv = {HTX_RISCV_GCC, "-march=rv32im", "-misa-spec=2.2",
                                   "-mabi=ilp32", "-nostdlib", "-nostartfiles",
                                   "-Wl,--no-warn-rwx-segments", "-I", HTX_ISA_TEST_DIR,
                                   "-T", HTX_ISA_TEST_DIR "/link.ld"};
  if (for_qemu) argv.push_back("-DHTX_QEMU");
  argv.insert(argv.end(), {"-o", elf.string(), source.string()});
  const RunResult r = run_program(argv, 60s);
  if (r.status == 0) return "";
  return "compiling " + source.string() + " failed (status " + std::to_string(r.status) + "):\n" +
         r.err;
}

// QEMU's signature: the program writes it as raw little-endian words on standard output.
std::vector<uint32_t> words_from_bytes(const std::string& bytes) {
  std::vector<uint32_t> words(bytes.size() / 4);
  for (size_t i = 0; i < words.size(); ++i) {
    uint32_t w = 0;
    for (int b = 3; b >= 0; --b) w = w << 8 | static_cast<uint8_t>(bytes[4 * i + b]);
    words[i] = w;
  }
  return words;
}

// htx_cpu_tb's --print-words lines: "sig[I] = DEC (0xHEX)".
std::vector<uint32_t> words_from_listing(const std::string& text) {
  std::vector<uint32_t> words;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    unsigned index = 0;
    uint32_t value = 0;
    if (std::sscanf(line.c_str(), "sig[%u] = %*u (0x%" SCNx32 ")", &index, &value) == 2 &&
        index == words.size()) {
      words.push_back(value);
    }
  }
  return words;
}

std::optional<uint64_t> instret_from_listing(const std::string& text) {
  const auto at = text.find("instret ");
  if (at == std::string::npos) return std::nullopt;
  return std::stoull(text.substr(at + 8));
}

// Empty when the core's words equal QEMU's, else where and how they first differ.
std::string first_difference(const std::vector<uint32_t>& core, const std::vector<uint32_t>& qemu) {
  for (uint32_t i = 0; i < kRandomProgramSignatureWords; ++i) {
    if (core[i] != qemu[i]) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "%s is 0x%08x on the core, 0x%08x in QEMU",
                    htx::cpu_tb::signature_word_name(i).c_str(), core[i], qemu[i]);
      return buf;
    }
  }
  return "";
}

uint64_t environment_number(const char* name, uint64_t fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const unsigned long long value = std::strtoull(text, &end, 10);
  if (*end != '\0' || value == 0) {
    ADD_FAILURE() << name << "=" << text << " is not a positive number; " << fallback << " used";
    return fallback;
  }
  return value;
}

// `htx sim --signature`'s file: 8 hex digits a line.
std::vector<uint32_t> words_from_signature_file(const fs::path& path) {
  std::vector<uint32_t> words;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) words.push_back(static_cast<uint32_t>(std::stoul(line, nullptr, 16)));
  return words;
}

// Runs the program for `seed` in QEMU and on the core, without and with wait states, and with
// `on_soc` on the whole SoC too (`htx sim`: the SoC's fabric and RAM, random wait states on every
// slave); empty when all agree, else what went wrong. Adds the core's instruction count to
// `instructions`.
std::string check_program(uint64_t seed, bool on_soc, uint64_t& instructions) {
  const ProgramFiles f = files_for(seed);
  std::ofstream(f.source) << htx::cpu_tb::random_program(seed);
  for (const auto& [elf, for_qemu] : {std::pair{f.core_elf, false}, std::pair{f.qemu_elf, true}}) {
    if (std::string error = compile(f.source, elf, for_qemu); !error.empty()) return error;
  }

  const std::vector<std::string> qemu_argv = {HTX_QEMU_RISCV32, f.qemu_elf.string()};
  const RunResult q = run_program(qemu_argv, 30s);
  const std::string qemu_command = command_line(qemu_argv);
  if (q.status != 0) return qemu_command + ": status " + std::to_string(q.status) + "\n" + q.err;
  if (q.out.size() != kRandomProgramSignatureWords * 4) {
    return qemu_command + ": " + std::to_string(q.out.size()) + " bytes of signature";
  }
  const std::vector<uint32_t> expected = words_from_bytes(q.out);

  // Without wait states, then with random ones on both buses (htx_cpu_tb's seed).
  for (const uint64_t stall_seed : {uint64_t{0}, seed}) {
    const std::vector<std::string> core_argv = {
        HTX_CPU_TB,     "--elf",   f.core_elf.string(), "--seed",
        std::to_string(stall_seed), "--max-cycles", "2000000", "--print-words",
        "sig:" + std::to_string(kRandomProgramSignatureWords)};
    const RunResult c = run_program(core_argv, 60s);
    const std::string core_command = command_line(core_argv);
    if (c.status != 0) {
      return core_command + ": status " + std::to_string(c.status) + " (SIM_EXIT " +
             std::to_string(htx::cpu_tb::kRandomProgramTrapExit) + " is a trap)\n" + c.out +
             c.err;
    }
    const std::vector<uint32_t> got = words_from_listing(c.out);
    const std::optional<uint64_t> instret = instret_from_listing(c.out);
    if (got.size() != kRandomProgramSignatureWords || !instret) {
      return core_command + ": no signature or instret in\n" + c.out;
    }
    if (std::string diff = first_difference(got, expected); !diff.empty()) {
      return core_command + " against " + qemu_command + ": " + diff + " (source " +
             f.source.string() + ")";
    }
    if (*instret < kLeastInstructions) {
      return core_command + ": only " + std::to_string(*instret) + " instructions";
    }
    if (stall_seed == 0) instructions += *instret;
  }
  if (on_soc) {
    fs::path signature = f.source;
    signature.replace_extension(".soc.sig");
    const std::vector<std::string> argv = {HTX_BIN, "sim", "--elf", f.core_elf.string(),
                                           "--signature", signature.string(), "--stall-seed",
                                           std::to_string(seed), "--max-cycles", "4000000"};
    const std::string soc_command = command_line(argv);
    const RunResult r = run_program(argv, 120s);
    if (r.status != 0) return soc_command + ": status " + std::to_string(r.status) + "\n" + r.err;
    const std::vector<uint32_t> got = words_from_signature_file(signature);
    if (got.size() != kRandomProgramSignatureWords) {
      return soc_command + ": " + std::to_string(got.size()) + " signature words";
    }
    if (std::string diff = first_difference(got, expected); !diff.empty()) {
      return soc_command + " against " + qemu_command + ": " + diff + " (source " +
             f.source.string() + ")";
    }
    fs::remove(signature);
  }
  fs::remove(f.source);
  fs::remove(f.core_elf);
  fs::remove(f.qemu_elf);
  return "";
}

class CpuAgainstQemu : public testing::TestWithParam<int> {};

TEST_P(CpuAgainstQemu, RandomProgramsLeaveTheSameRegistersAndMemory) {
  const uint64_t per_case = environment_number("HTX_CPU_DIFF_PER_CASE", 16);
  const uint64_t first =
      environment_number("HTX_CPU_DIFF_FIRST_SEED", 1) + static_cast<uint64_t>(GetParam()) * per_case;
  const uint64_t on_soc_per_case = environment_number("HTX_CPU_DIFF_ON_SOC", 2);
  uint64_t instructions = 0;
  for (uint64_t seed = first; seed < first + per_case; ++seed) {
    const bool on_soc = seed - first < on_soc_per_case;
    EXPECT_EQ(check_program(seed, on_soc, instructions), "") << "seed " << seed;
  }
  std::printf("seeds %" PRIu64 " to %" PRIu64 ": %" PRIu64 " instructions on the core\n", first,
              first + per_case - 1, instructions);
}

INSTANTIATE_TEST_SUITE_P(Seeds, CpuAgainstQemu, testing::Range(0, kCases));

// The generator is deterministic: a seed gives the same program every time, so a failing seed
// reproduces.
TEST(RandomProgram, ASeedGivesTheSameProgram) {
  EXPECT_EQ(htx::cpu_tb::random_program(5), htx::cpu_tb::random_program(5));
  EXPECT_NE(htx::cpu_tb::random_program(5), htx::cpu_tb::random_program(6));
}

}  // namespace
