// htx sim's contract beyond the firmware: every run ends (cycle limit: clear message, status 124),
// bad input is refused with a clear message, the tohost convention sets the status, --signature
// writes the words between begin_signature and end_signature, --json prints one object, and
// --profile charges every clock to one cause, each cause counted as the pipeline's rules say, and
// --hotspots every clock to a function.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "sim_json.hpp"
#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;
using htx::test::last_json_line;

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
  const auto json = last_json_line(r.out);
  EXPECT_EQ(json.at("reason"), "cycle_limit");
  EXPECT_EQ(json.at("cycles"), 20000);
  EXPECT_EQ(json.at("exit_code"), 124);
  // The summary gives no exit code: the firmware never exited.
  EXPECT_NE(r.err.find("htx sim: cycle_limit: 20000 cycles"), std::string::npos) << r.err;
}

// A command line htx cannot take ends with its message and status 2, whatever its kind (a missing
// option, a value of the wrong type, an unknown option, a file that does not exist); --help and
// --version with 0; an error found later (no such scene) with 1.
TEST(SystemSimCli, CommandLineErrorsEndWithStatusTwo) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> usage = {
      {{HTX_BIN, "sim"}, "--elf is required"},
      {{HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--max-cycles", "many"}, "--max-cycles"},
      {{HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--no-such-option"}, "--no-such-option"},
      {{HTX_BIN, "compare", temp_path("none_a.png"), temp_path("none_b.png")}, "File does not exist"},
      {{HTX_BIN}, "A subcommand is required"},
      {{HTX_BIN, "--bogus"}, "htx: no option '--bogus' before a command"},
      // Whole numbers are decimal digits that fit 64 bits (CLI11 alone read 0x10 as 16, wrapped a
      // negative number and saturated a large one).
      {{HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--max-cycles", "0x10"},
       "--max-cycles: want a whole number >= 0 in decimal digits, not 0x10"},
      {{HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--max-cycles", "-18446744073709551515"},
       "--max-cycles: want a whole number >= 0 in decimal digits, not -18446744073709551515"},
      {{HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--stall-seed", "99999999999999999999"},
       "--stall-seed: 99999999999999999999 does not fit 64 bits"}};
  for (const auto& [argv, message] : usage) {
    const auto r = htx::test::run_program(argv, 30s);
    EXPECT_EQ(r.status, 2) << argv.back() << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  for (const char* flag : {"--help", "--version"}) EXPECT_EQ(htx::test::run_program({HTX_BIN, flag}, 30s).status, 0);
  EXPECT_EQ(htx::test::run_program({HTX_BIN, "sim", "--help"}, 30s).status, 0);
  const auto later = htx::test::run_program({HTX_BIN, "render", "nosuch", "--out", temp_path("x.png")}, 30s);
  EXPECT_EQ(later.status, 1) << later.err;
}

// A run in which no instruction retires for 2^23 clocks (here a trap loop: an illegal instruction
// at mtvec) ends there with a message that says so and status 1, not at the cycle limit minutes
// later with advice to raise it.
TEST(SystemSimCli, ARunThatRetiresNothingEndsAsStuck) {
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_SYSTEM_TEST_ELF_DIR "/sim_trap_loop.elf", "--json"}, 90s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("no instruction retired in 8388608 cycles (execute stage at pc 0x00000000): the CPU "
                       "traps in a loop"),
            std::string::npos)
      << r.err;
  const auto json = last_json_line(r.out);
  EXPECT_EQ(json.at("reason"), "stuck");
  EXPECT_EQ(json.at("instret"), 0);
  EXPECT_EQ(json.at("exit_code"), 1);
  EXPECT_LT(json.at("cycles").get<uint64_t>(), 8388608u + 512u);
}

// A whole number with leading zeros is decimal (CLI11 alone read 0100 as octal, 64), and a frame
// size is two decimal numbers (sscanf's %u took -4294967295 as 1).
TEST(SystemSimCli, WholeNumbersAreDecimalAndFrameSizesExact) {
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--max-cycles", "0100"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 124);
  EXPECT_NE(r.err.find("cycle limit of 100 cycles reached"), std::string::npos) << r.err;
  for (const char* size : {"-4294967295x10", "4294967297x1", "+8x8", " 8x8", "8x8x"}) {
    const auto bad = htx::test::run_program({HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--max-cycles",
                                             "100", "--frame-size", size, "--frame", temp_path("size.png")},
                                            60s);
    EXPECT_EQ(bad.status, 1) << size;
    EXPECT_NE(bad.err.find(std::string("--frame-size '") + size + "' is not WIDTHxHEIGHT"), std::string::npos)
        << bad.err;
  }
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

TEST(SystemSimCli, OutputsThatCannotBeWrittenAreRefusedBeforeTheRun) {
  // echo.elf has no signature symbols and would run to the cycle limit: both refusals come first.
  const std::string dir = temp_path("no_such_dir");
  const struct {
    std::vector<std::string> option;
    std::string message;
  } cases[] = {
      {{"--signature", temp_path("sig.txt")}, "the ELF has no begin_signature/end_signature symbols"},
      {{"--frame", dir + "/frame.png"}, "no directory " + dir + " to write it in"},
      {{"--screen", dir + "/screen.png"}, "no directory " + dir + " to write it in"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--max-cycles", "2000000"};
    args.insert(args.end(), c.option.begin(), c.option.end());
    const auto r = htx::test::run_program(args, 60s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("cycle limit"), std::string::npos) << "refused only after the run: " << r.err;
    EXPECT_EQ(r.out.find("hypertex echo"), std::string::npos) << "the firmware ran: " << r.out;
  }
}

// A write that fails (here /dev/full: no space left) is an error, not a file reported as written.
TEST(SystemSimCli, ASignatureThatCannotBeWrittenIsAnError) {
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_SIM_TEST_ELF, "--signature", "/dev/full", "--max-cycles", "100000"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("cannot write '/dev/full': No space left on device"), std::string::npos) << r.err;
}

std::string elf_variant(const std::string& name) { return HTX_SYSTEM_TEST_ELF_DIR "/" + name + ".elf"; }

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// What the harness cannot run, or cannot read after the run, is refused before the run (no summary,
// nothing opened), naming the ELF.
TEST(SystemSimCli, ImagesTheHarnessCannotRunAreRefusedBeforeTheRun) {
  const std::string trace = temp_path("refused.fst");
  const struct {
    std::string elf;
    std::vector<std::string> options;
    std::string message;
  } cases[] = {
      {elf_variant("sim_skewed_signature"), {"--signature", temp_path("skewed.sig")},
       "begin_signature/end_signature [0x"},
      {elf_variant("sim_tohost_set"), {}, "holds 0x00000055 in the image: the run would end in its first clock"},
      {HTX_OFFSET_ENTRY_ELF, {"--trace", trace}, "entry point 0x00000100 is not the SoC's reset vector"},
  };
  for (const auto& c : cases) {
    std::remove(trace.c_str());
    std::vector<std::string> args = {HTX_BIN, "sim", "--elf", c.elf, "--max-cycles", "3000000"};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const auto r = htx::test::run_program(args, 60s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find(c.elf + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("cycles"), std::string::npos) << "refused only after the run: " << r.err;
    EXPECT_FALSE(std::ifstream(trace).good()) << "the trace was opened before the refusal";
  }
}

// FST's writer deletes what is at its path, and an output must not overwrite the ELF it runs.
TEST(SystemSimCli, OutputsThatWouldReplaceTheElfALinkOrADeviceAreRefused) {
  const std::string elf = temp_path("own.elf");
  const std::string original = read_file(HTX_SIM_TEST_ELF);
  ASSERT_FALSE(original.empty());
  std::ofstream(elf, std::ios::binary) << original;
  const std::string link = temp_path("link.fst"), target = temp_path("link_target.fst");
  std::ofstream(target) << "kept\n";
  std::remove(link.c_str());
  ASSERT_EQ(::symlink(target.c_str(), link.c_str()), 0);
  const struct {
    std::vector<std::string> options;
    std::string message;
  } cases[] = {
      {{"--signature", elf}, "is the ELF being run"},
      {{"--trace", elf}, "is the ELF being run"},
      {{"--trace", link}, "is a symbolic link"},
      {{"--trace", "/dev/null"}, "is not a regular file"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {HTX_BIN, "sim", "--elf", elf, "--max-cycles", "100000"};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const auto r = htx::test::run_program(args, 60s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(read_file(elf), original) << "the ELF was overwritten";
  }
  struct stat st {};
  ASSERT_EQ(::lstat(link.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode)) << "the link was replaced";
  EXPECT_EQ(read_file(target), "kept\n");
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null was replaced";
}

// A status is one byte: an exit code that does not fit gives 1, never its low byte (256 would read
// as success); the code itself is in the JSON, which is a line of its own after the firmware's
// output, even when that ended without a newline.
TEST(SystemSimCli, AnExitCodeNoProcessCanHaveIsStatusOne) {
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", elf_variant("sim_code256"), "--json"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("exit code 256 (not a process status: status 1)"), std::string::npos) << r.err;
  ASSERT_EQ(r.out.rfind("A\n{", 0), 0u) << r.out;
  const auto json = nlohmann::json::parse(r.out.substr(2));
  EXPECT_EQ(json.at("exit_code"), 1);
  EXPECT_EQ(json.at("firmware_code"), 256);
  EXPECT_EQ(json.at("reason"), "tohost");
}

// An instruction test that traps before its first test case fails (tohost's pass code is
// (0 << 1) | 1, which such a failure used to write).
TEST(SystemSimCli, AnInstructionTestThatTrapsBeforeItsFirstCaseFails) {
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", elf_variant("isa_early_trap"), "--json", "--max-cycles", "100000"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 127) << r.err;  // HTX_TEST_BEFORE_FIRST
  EXPECT_EQ(last_json_line(r.out).at("reason"), "tohost");
}

// An output that fails after the run does not lose the run: the summary and the JSON still come,
// the other outputs are written, and the status is 1.
TEST(SystemSimCli, AFailedOutputStillReportsTheRunAndWritesTheOthers) {
  const std::string sig = temp_path("beside_full.sig");
  std::remove(sig.c_str());
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", HTX_SIM_TEST_ELF, "--frame", "/dev/full",
                                         "--signature", sig, "--json", "--max-cycles", "100000"},
                                        60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("tohost, exit code 3"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  const auto json = last_json_line(r.out);
  EXPECT_EQ(json.at("exit_code"), 1);
  EXPECT_EQ(json.at("firmware_code"), 3);
  ASSERT_EQ(json.at("errors").size(), 1u);
  EXPECT_EQ(read_file(sig), "deadbeef\n00000000\n12345678\nfffffff9\n");
}

// The firmware's output and the JSON go to standard output: when it cannot be written (here
// /dev/full), the run is reported on stderr and the status is 1, not the firmware's 0.
TEST(SystemSimCli, AStandardOutputThatCannotBeWrittenIsStatusOne) {
  const std::string command = std::string("exec '") + HTX_BIN + "' sim --elf '" + HTX_FIRMWARE_DIR +
                              "/hello.elf' --json --max-cycles 5000000 >/dev/full";
  const auto r = htx::test::run_program({"/bin/sh", "-c", command}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("exit, exit code 0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("standard output could not be written"), std::string::npos) << r.err;
}

// --screen-frames: the directory's pictures from an earlier run are removed first (the set is this
// run's); a picture that cannot be written ends the recording, not the run (the run is reported,
// the other outputs written, status 1); a path that is a file is refused before the run.
TEST(SystemSimCli, ScreenFramesAreThisRunsAndAFailedOneDoesNotLoseTheRun) {
  namespace fs = std::filesystem;
  const std::string dir = temp_path("screen_frames");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir + "/screen_0005.png") << "stale";
  std::ofstream(dir + "/notes.txt") << "kept";
  // The console turns the video on at boot; the first whole frame ends after 420,000 clocks.
  const std::vector<std::string> run = {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/console.elf", "--max-cycles",
                                        "1000000", "--json"};
  auto args = run;
  args.insert(args.end(), {"--screen-frames", dir});
  auto r = htx::test::run_program(args, 120s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 124) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/screen_0000.png"));
  EXPECT_FALSE(fs::exists(dir + "/screen_0005.png"));
  EXPECT_TRUE(fs::exists(dir + "/notes.txt"));

  // screen_0000.png a directory: the picture cannot be written.
  fs::remove(dir + "/screen_0000.png");
  fs::create_directories(dir + "/screen_0000.png/x");
  const std::string frame = temp_path("beside_screen_frames.png");
  std::remove(frame.c_str());
  args = run;
  args.insert(args.end(), {"--screen-frames", dir, "--frame", frame});
  r = htx::test::run_program(args, 120s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("htx sim: cycle_limit: 1000000 cycles"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no more pictures written"), std::string::npos) << r.err;
  const auto json = last_json_line(r.out);
  EXPECT_EQ(json.at("errors").size(), 1u);
  EXPECT_TRUE(fs::exists(frame));

  args = run;
  args.insert(args.end(), {"--screen-frames", frame});
  r = htx::test::run_program(args, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--screen-frames needs a directory"), std::string::npos) << r.err;
  args = run;
  args.insert(args.end(), {"--screen-frames", temp_path("same_path"), "--screen", temp_path("same_path")});
  r = htx::test::run_program(args, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("is also --screen-frames' directory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(temp_path("same_path")));
}

// An ELF is read from a regular file only: a device would be read until memory ran out.
TEST(SystemSimCli, AnElfThatIsNotARegularFileIsRefused) {
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", "/dev/zero", "--max-cycles", "1000"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/dev/zero: not a regular file"), std::string::npos) << r.err;
}

// SIGINT ends the run as the cycle limit does: the summary, a whole trace, status 130.
TEST(SystemSimCli, AnInterruptEndsTheRunAndClosesTheTrace) {
  const std::string trace = temp_path("interrupted.fst");
  std::remove(trace.c_str());
  htx::test::Child sim(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--uart", "pty", "--trace", trace, "--json"});
  ASSERT_TRUE(sim.read_until("UART on", 30s)) << sim.output();
  std::this_thread::sleep_for(500ms);
  sim.send_signal(SIGINT);
  ASSERT_TRUE(sim.read_until("\"reason\":\"stopped\"", 60s)) << sim.output();
  EXPECT_EQ(sim.wait(30s), 130);
  const auto json = last_json_line(sim.output());
  EXPECT_EQ(json.at("exit_code"), 130);
  EXPECT_GT(json.at("cycles").get<uint64_t>(), 0u);
  // A closed FST file ends with its hierarchy; an interrupted writer leaves a .hier file beside it.
  EXPECT_FALSE(std::ifstream(trace + ".hier").good());
  EXPECT_GT(read_file(trace).size(), 1000u);
}

TEST(SystemSimCli, ToHostStatusAndSignature) {
  const std::string sig = temp_path("signature.txt");
  std::remove(sig.c_str());
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_SIM_TEST_ELF, "--signature", sig, "--json", "--max-cycles", "100000"}, 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 3) << r.err;  // the program writes tohost = (3 << 1) | 1
  const auto json = last_json_line(r.out);
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

// The profile of sim_profile.S (LOOPS iterations) as a cause -> clocks map, checking that the
// causes add up to the run's clocks.
std::map<std::string, uint64_t> profile_of(const std::vector<std::string>& extra_args, unsigned loops) {
  std::vector<std::string> argv = {HTX_BIN, "sim", "--elf",
                                   std::string(HTX_SIM_PROFILE_ELF_DIR) + "/sim_profile_" + std::to_string(loops) + ".elf",
                                   "--profile", "--json", "--max-cycles", "1000000"};
  argv.insert(argv.end(), extra_args.begin(), extra_args.end());
  const auto r = htx::test::run_program(argv, 60s);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("where the CPU's"), std::string::npos) << r.err;
  const auto json = last_json_line(r.out);
  std::map<std::string, uint64_t> out;
  uint64_t sum = 0;
  for (const auto& [cause, clocks] : json.at("profile").items()) {
    out[cause] = clocks.get<uint64_t>();
    sum += out[cause];
  }
  EXPECT_EQ(out.size(), 9u);
  EXPECT_EQ(sum, json.at("cycles").get<uint64_t>()) << json.dump();
  // Every instruction that retires left execute (the last ones may still be in write-back).
  EXPECT_GE(out["execute"], json.at("instret").get<uint64_t>());
  EXPECT_LE(out["execute"], json.at("instret").get<uint64_t>() + 2);
  return out;
}

TEST(SystemSimCli, ProfileChargesEachLoopIterationItsKnownClocks) {
  // 200 more iterations: each executes 9 instructions and loses one clock to a load's data used
  // next, two to shift results used next (forwarded from write-back only) and one to a multiply
  // whose source the instruction before writes, two to the multiplier and one to the
  // predicted-taken branch's bubble; nothing else changes.
  const auto short_run = profile_of({}, 100);
  const auto long_run = profile_of({}, 300);
  const std::map<std::string, uint64_t> per_iteration = {
      {"execute", 9}, {"load_use", 1}, {"late_result", 3}, {"mul_div", 2}, {"jump", 1},
      {"data_bus", 0}, {"csr_order", 0}, {"redirect", 0}, {"fetch", 0}};
  for (const auto& [cause, clocks] : per_iteration) {
    EXPECT_EQ(long_run.at(cause) - short_run.at(cause), 200 * clocks) << cause;
  }
}

TEST(SystemSimCli, ProfileCountsWaitStates) {
  // With random wait states on every slave the same program loses clocks to both buses.
  const auto quiet = profile_of({}, 100);
  const auto stalled = profile_of({"--stall-seed", "7"}, 100);
  EXPECT_EQ(quiet.at("data_bus"), 0u);
  EXPECT_GT(stalled.at("data_bus"), 0u);
  // Instruction-bus wait states while fetch refills behind a predicted jump are the jump's.
  EXPECT_GT(stalled.at("jump"), quiet.at("jump"));
  EXPECT_GT(stalled.at("fetch") + stalled.at("redirect"), quiet.at("fetch") + quiet.at("redirect"));
  EXPECT_GT(stalled.at("mul_div"), 0u);
}

TEST(SystemSimCli, NoProfileUnlessAsked) {
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", HTX_SIM_TEST_ELF, "--json"}, 60s);
  const auto json = last_json_line(r.out);
  EXPECT_FALSE(json.contains("profile"));
  EXPECT_FALSE(json.contains("hotspots"));
  EXPECT_EQ(r.err.find("where the CPU's"), std::string::npos) << r.err;
}

// --hotspots on sim_profile.S, whose loop lies in _start (a label without a size, bounded by its
// section): 200 more iterations charge _start exactly 200 times the iteration's 16 clocks (the
// bubbles included: each goes to the instruction before it) and 9 instructions.
TEST(SystemSimCli, HotspotsChargeEachLoopIterationToItsFunction) {
  auto hotspots_of = [](unsigned loops) {
    const auto r = htx::test::run_program(
        {HTX_BIN, "sim", "--elf", std::string(HTX_SIM_PROFILE_ELF_DIR) + "/sim_profile_" + std::to_string(loops) + ".elf",
         "--hotspots", "--json", "--max-cycles", "1000000"},
        60s);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("went by function"), std::string::npos) << r.err;
    const auto json = last_json_line(r.out);
    EXPECT_EQ(json.at("hotspots").size(), 1u) << json.dump();
    const auto& start = json.at("hotspots").at(0);
    EXPECT_EQ(start.at("function"), "_start");
    EXPECT_EQ(start.at("cycles").get<uint64_t>(), json.at("cycles").get<uint64_t>());
    return std::pair{start.at("cycles").get<uint64_t>(), start.at("instructions").get<uint64_t>()};
  };
  const auto [short_clocks, short_instructions] = hotspots_of(100);
  const auto [long_clocks, long_instructions] = hotspots_of(300);
  EXPECT_EQ(long_clocks - short_clocks, 200u * 16u);
  EXPECT_EQ(long_instructions - short_instructions, 200u * 9u);
}

// Calls (tests/system/sim_calls.S): each function's calls and callers, `leaf`'s inclusive clocks
// its own, `outer`'s its own with `leaf`'s and those of `tail`, which it jumps into (not a call).
TEST(SystemSimCli, HotspotsFollowCallsAndReturns) {
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", HTX_SIM_CALLS_ELF, "--hotspots", "--json"}, 60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("inclusive"), std::string::npos) << r.err;
  const auto json = last_json_line(r.out);
  std::map<std::string, nlohmann::json> fn;
  uint64_t sum = 0;
  for (const auto& h : json.at("hotspots")) {
    fn[h.at("function").get<std::string>()] = h;
    sum += h.at("cycles").get<uint64_t>();
  }
  ASSERT_EQ(fn.size(), 4u) << json.dump();
  EXPECT_EQ(sum, json.at("cycles").get<uint64_t>());
  const auto& leaf = fn.at("leaf");
  const auto& outer = fn.at("outer");
  EXPECT_EQ(leaf.at("calls"), 100);  // through JAL and JALR
  EXPECT_EQ(leaf.at("instructions"), 100 * 12);
  EXPECT_EQ(leaf.at("inclusive"), leaf.at("cycles"));
  EXPECT_EQ(leaf.at("callers"), nlohmann::json::parse(R"([{"function":"outer","calls":100}])"));
  EXPECT_EQ(outer.at("calls"), 50);
  EXPECT_EQ(outer.at("inclusive").get<uint64_t>(), outer.at("cycles").get<uint64_t>() +
                                                       leaf.at("cycles").get<uint64_t>() +
                                                       fn.at("tail").at("cycles").get<uint64_t>());
  EXPECT_EQ(outer.at("callers"), nlohmann::json::parse(R"([{"function":"_start","calls":50}])"));
  EXPECT_EQ(fn.at("tail").at("calls"), 0);
  EXPECT_EQ(fn.at("tail").at("inclusive"), 0);
  EXPECT_EQ(fn.at("_start").at("calls"), 0);
}

}  // namespace
