// The board commands of htx: `htx image` (a firmware ELF as a board's RAM initialisation) against
// the toolchain's own flat binary of the ELF, and `htx flash` against a stand-in loader that records
// its command line (openFPGALoader's for the ULX3S, iceprog's for the iCEBreaker).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HtxImage, WordsAreTheElfsLoadImageAndTheRestZero) {
  const std::string hex = ::testing::TempDir() + "htx_image_echo.hex";
  const std::string bin = ::testing::TempDir() + "htx_image_echo.bin";
  const auto r = htx::test::run_program(
      {HTX_BIN, "image", HTX_FIRMWARE_DIR "/echo.elf", "-o", hex, "--ram-bytes", "65536"}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("16384 words (65536-byte RAM)"), std::string::npos) << r.out;
  // The toolchain's flat binary holds every loaded byte from address 0 to the last one.
  const auto o = htx::test::run_program({HTX_RISCV_OBJCOPY, "-O", "binary", HTX_FIRMWARE_DIR "/echo.elf", bin}, 60s);
  ASSERT_EQ(o.status, 0) << o.err;
  const std::string flat = read_file(bin);
  ASSERT_GT(flat.size(), 1000u);

  std::ifstream in(hex);
  std::string line;
  uint32_t index = 0;
  while (std::getline(in, line)) {
    ASSERT_EQ(line.size(), 8u) << "line " << index;
    ASSERT_EQ(line.find_first_not_of("0123456789abcdef"), std::string::npos) << line;
    uint32_t expected = 0;
    for (uint32_t b = 0; b < 4; ++b) {
      const size_t at = index * 4 + b;
      if (at < flat.size()) expected |= static_cast<uint32_t>(static_cast<uint8_t>(flat[at])) << (8 * b);
    }
    ASSERT_EQ(std::stoul(line, nullptr, 16), expected) << "word " << index;
    ++index;
  }
  EXPECT_EQ(index, 16384u);
}

TEST(HtxImage, RefusesAFirmwareLargerThanTheRamANonElfAndAnEntryOffTheResetVector) {
  const std::string hex = ::testing::TempDir() + "htx_image_small.hex";
  const auto small = htx::test::run_program(
      {HTX_BIN, "image", HTX_FIRMWARE_DIR "/console.elf", "-o", hex, "--ram-bytes", "32768"}, 60s);
  EXPECT_NE(small.status, 0);
  EXPECT_NE(small.err.find("does not fit in the 32768-byte RAM at 0"), std::string::npos) << small.err;
  const std::string text = ::testing::TempDir() + "htx_image_not_elf.txt";
  std::ofstream(text) << "not an ELF file\n";
  const auto bad = htx::test::run_program({HTX_BIN, "image", text, "-o", hex}, 60s);
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("htx image: " + text), std::string::npos) << bad.err;
  // The test program whose entry is not at 0 (the SoC would start it elsewhere).
  const auto entry = htx::test::run_program({HTX_BIN, "image", HTX_OFFSET_ENTRY_ELF, "-o", hex}, 60s);
  EXPECT_NE(entry.status, 0);
  EXPECT_NE(entry.err.find("is not the SoC's reset vector 0x00000000"), std::string::npos) << entry.err;
}

// A stand-in for openFPGALoader: writes its arguments, one a line, and exits with STATUS.
std::string fake_loader(const std::string& name, int status) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << "#!/bin/sh\nfor a in \"$@\"; do echo \"$a\"; done > \"$0.args\"\nexit " << status << "\n";
  chmod(path.c_str(), 0755);
  return path;
}

TEST(HtxFlash, RunsEachBoardsLoaderIntoTheFpgaOrItsFlash) {
  const std::string bit = ::testing::TempDir() + "htx_flash_test.bit";
  std::ofstream(bit) << "bitstream bytes";
  const std::string loader = fake_loader("htx_fake_loader_ok", 0);

  auto r = htx::test::run_program({HTX_BIN, "flash", bit, "--loader", loader}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(loader + ".args"), "-b\nulx3s\n" + bit + "\n");
  EXPECT_NE(r.out.find("loaded " + bit + " into the FPGA"), std::string::npos) << r.out;

  r = htx::test::run_program({HTX_BIN, "flash", bit, "--flash", "--loader", loader}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(loader + ".args"), "-b\nulx3s\n-f\n" + bit + "\n");
  EXPECT_NE(r.out.find("into the board's flash"), std::string::npos) << r.out;

  // The iCEBreaker's loader is iceprog: the flash by default (a stock board takes no SRAM load),
  // -S for the FPGA's SRAM with --sram.
  r = htx::test::run_program({HTX_BIN, "flash", bit, "--board", "icebreaker", "--loader", loader}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(loader + ".args"), bit + "\n");
  EXPECT_NE(r.out.find("into the board's flash"), std::string::npos) << r.out;
  r = htx::test::run_program({HTX_BIN, "flash", bit, "--board", "icebreaker", "--flash", "--loader", loader}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(loader + ".args"), bit + "\n");
  r = htx::test::run_program({HTX_BIN, "flash", bit, "--board", "icebreaker", "--sram", "--loader", loader}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(loader + ".args"), "-S\n" + bit + "\n");
  EXPECT_NE(r.out.find("into the FPGA"), std::string::npos) << r.out;
  r = htx::test::run_program({HTX_BIN, "flash", bit, "--board", "icebreaker", "--sram", "--dry-run"}, 60s);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("htx flash: iceprog -S " + bit), std::string::npos) << r.out;
  // The ULX3S's --sram is its default; both flags at once are refused.
  r = htx::test::run_program({HTX_BIN, "flash", bit, "--sram", "--loader", loader}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(loader + ".args"), "-b\nulx3s\n" + bit + "\n");
  r = htx::test::run_program({HTX_BIN, "flash", bit, "--sram", "--flash", "--dry-run"}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--flash and --sram"), std::string::npos) << r.err;
}

TEST(HtxFlash, ReportsALoaderThatFailsOrIsMissingAndAnEmptyFile) {
  const std::string bit = ::testing::TempDir() + "htx_flash_test2.bit";
  std::ofstream(bit) << "bitstream bytes";
  auto r = htx::test::run_program({HTX_BIN, "flash", bit, "--loader", fake_loader("htx_fake_loader_fail", 3)}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("failed (exit status 3)"), std::string::npos) << r.err;

  // A loader of the user's own that is missing: no package advice (it would be wrong); the
  // default loader missing from PATH: the package that brings it.
  r = htx::test::run_program({HTX_BIN, "flash", bit, "--loader", "/nonexistent/openFPGALoader"}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot run /nonexistent/openFPGALoader"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("apt-get"), std::string::npos) << r.err;
  r = htx::test::run_program(
      {"/bin/sh", "-c", std::string("PATH=/nonexistent exec '") + HTX_BIN + "' flash '" + bit + "'"}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("apt-get install openfpgaloader"), std::string::npos) << r.err;

  const std::string empty = ::testing::TempDir() + "htx_flash_empty.bit";
  std::ofstream{empty};
  r = htx::test::run_program({HTX_BIN, "flash", empty, "--loader", "/bin/true"}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("is empty"), std::string::npos) << r.err;

  r = htx::test::run_program({HTX_BIN, "flash", bit, "--board", "tangnano", "--dry-run"}, 60s);
  EXPECT_NE(r.status, 0);

  r = htx::test::run_program({HTX_BIN, "flash", "/dev/null", "--dry-run"}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/dev/null: not a file"), std::string::npos) << r.err;
}

// A bitstream whose relative path starts with '-' reaches the loader as a path, not an option.
TEST(HtxFlash, ABitstreamNamedLikeAnOptionIsPassedAsAPath) {
  const std::string dir = ::testing::TempDir() + "htx_flash_dash";
  mkdir(dir.c_str(), 0755);
  std::ofstream(dir + "/-v.bit") << "bitstream bytes";
  const std::string loader = fake_loader("htx_fake_loader_dash", 0);
  const auto r = htx::test::run_program(
      {"/bin/sh", "-c",
       "cd '" + dir + "' && exec '" + HTX_BIN + "' flash --board icebreaker --loader '" + loader + "' -- -v.bit"},
      60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(loader + ".args"), "./-v.bit\n");
}

// htx image writes its output only where it would not destroy the ELF it reads, and refuses an
// empty output path, before it reads anything.
TEST(HtxImage, RefusesToWriteOverItsElfOrToAnEmptyPath) {
  const std::string elf = ::testing::TempDir() + "htx_image_self.elf";
  {
    std::ifstream in(HTX_FIRMWARE_DIR "/hello.elf", std::ios::binary);
    std::ofstream out(elf, std::ios::binary);
    out << in.rdbuf();
  }
  const std::string before = read_file(elf);
  auto r = htx::test::run_program({HTX_BIN, "image", elf, "-o", elf}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("writing it would destroy it"), std::string::npos) << r.err;
  EXPECT_EQ(read_file(elf), before);
  r = htx::test::run_program({HTX_BIN, "image", elf, "-o", ""}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("-o: an empty path"), std::string::npos) << r.err;
}

}  // namespace
