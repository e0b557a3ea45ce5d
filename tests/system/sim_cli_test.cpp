// htx sim's contract beyond the firmware: every run ends (cycle limit: clear message, status 124),
// bad input is refused with a clear message, the tohost convention sets the status, --signature
// writes the words between begin_signature and end_signature, and --json prints one object.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + "htx_sim_cli_" + name;
}

TEST(SystemSimCli, CycleLimitEndsTheRunWithAClearMessage) {
  // The echo firmware waits for input forever; only the limit can end it.
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--max-cycles", "20000", "--json"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 124);
  EXPECT_NE(r.err.find("cycle limit of 20000 cycles reached"), std::string::npos) << r.err;
  const auto json = nlohmann::json::parse(r.out.substr(r.out.rfind('{')));
  EXPECT_EQ(json.at("reason"), "cycle_limit");
  EXPECT_EQ(json.at("cycles"), 20000);
  EXPECT_EQ(json.at("exit_code"), 124);
}

TEST(SystemSimCli, RefusesAFileThatIsNotAnElf) {
  const std::string bad = temp_path("not_an_elf.txt");
  std::ofstream(bad) << "this is not an ELF file\n";
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", bad}, 30s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("not a usable RISC-V ELF32 executable: bad magic"), std::string::npos) << r.err;
}

TEST(SystemSimCli, RefusesATruncatedElf) {
  std::ifstream in(HTX_FIRMWARE_DIR "/echo.elf", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 200u);
  const std::string cut = temp_path("truncated.elf");
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, 100);
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", cut}, 30s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("outside the file"), std::string::npos) << r.err;
}

TEST(SystemSimCli, ToHostStatusAndSignature) {
  const std::string sig = temp_path("signature.txt");
  std::remove(sig.c_str());
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_SIM_TEST_ELF, "--signature", sig, "--json", "--max-cycles", "100000"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 3) << r.err;  // the program writes tohost = (3 << 1) | 1
  const auto json = nlohmann::json::parse(r.out.substr(r.out.rfind('{')));
  EXPECT_EQ(json.at("reason"), "tohost");
  EXPECT_GT(json.at("instret").get<uint64_t>(), 5u);
  EXPECT_GT(json.at("cpi").get<double>(), 0.5);

  std::ifstream in(sig);
  std::stringstream text;
  text << in.rdbuf();
  // The program stores these computed values between begin_signature and end_signature.
  EXPECT_EQ(text.str(), "deadbeef\n00000000\n12345678\nfffffff9\n");
}

TEST(SystemSimCli, SameResultWithRandomStalls) {
  const std::string sig = temp_path("signature_stall.txt");
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", HTX_SIM_TEST_ELF, "--signature", sig,
                                         "--stall-seed", "99", "--max-cycles", "100000"}, 60s);
  EXPECT_EQ(r.status, 3) << r.err;
  std::ifstream in(sig);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "deadbeef\n00000000\n12345678\nfffffff9\n");
}

}  // namespace
