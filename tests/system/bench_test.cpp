// The benchmark firmware runs to completion on the simulated SoC and its kernel checksums equal
// the host's results for the same kernels (the same source, firmware/app/bench/kernels.cpp).
// Speed is reported (printed and recorded as test properties), not asserted.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "kernels.hpp"
#include "sim_json.hpp"
#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::map<std::string, std::string> checksums_from(const std::string& out) {
  std::map<std::string, std::string> sums;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    char name[32];
    unsigned sum = 0;
    if (std::sscanf(line.c_str(), "bench %31s cycles %*u instret %*u cpi %*u.%*u checksum %x", name,
                    &sum) == 2) {
      char hex[16];
      std::snprintf(hex, sizeof hex, "%08x", sum);
      sums[name] = hex;
    }
  }
  return sums;
}

TEST(SystemBench, RunsToCompletionWithHostChecksums) {
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/bench.elf", "--max-cycles", "20000000", "--json"}, 120s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;

  const auto sums = checksums_from(r.out);
  ASSERT_EQ(sums.size(), htx::bench::kKernelCount) << r.out;
  for (unsigned k = 0; k < htx::bench::kKernelCount; ++k) {
    const auto& spec = htx::bench::kKernels[k];
    spec.prepare(spec.seed, spec.n);
    char want[16];
    std::snprintf(want, sizeof want, "%08x", spec.run(spec.n));
    ASSERT_TRUE(sums.count(spec.name)) << spec.name << " missing in\n" << r.out;
    EXPECT_EQ(sums.at(spec.name), want) << "kernel " << spec.name;
  }

  // The figures: the firmware's own total (kernels only) and the whole run from the harness.
  const size_t total = r.out.find("bench total");
  ASSERT_NE(total, std::string::npos) << r.out;
  const std::string total_line = r.out.substr(total, r.out.find('\n', total) - total);
  const auto json = htx::test::last_json_line(r.out);
  EXPECT_EQ(json.at("exit_code"), 0);
  EXPECT_EQ(json.at("reason"), "exit");
  std::printf("%s\nwhole run: %s\n", total_line.c_str(), json.dump().c_str());
  ::testing::Test::RecordProperty("bench_total", total_line);
  ::testing::Test::RecordProperty("sim_cycles_per_second",
                                  std::to_string(json.at("cycles_per_second").get<double>()));
}

// --hotspots charges the kernels' clocks to their functions: transform and clip run in leaf
// functions, whose clocks are the firmware's own rdcycle figures less the reading's few clocks.
TEST(SystemBench, HotspotsChargeTheLeafKernelsTheirClocks) {
  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/bench.elf", "--max-cycles", "20000000", "--hotspots", "--json"},
      120s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.err.find("by function"), std::string::npos) << r.err;
  const auto json = htx::test::last_json_line(r.out);
  std::map<std::string, uint64_t> cycles;
  uint64_t sum = 0, instructions = 0;
  for (const auto& h : json.at("hotspots")) {
    cycles[h.at("function").get<std::string>()] = h.at("cycles").get<uint64_t>();
    sum += h.at("cycles").get<uint64_t>();
    instructions += h.at("instructions").get<uint64_t>();
  }
  EXPECT_EQ(sum, json.at("cycles").get<uint64_t>());
  // Instructions execute completed: minstret's, and the last few that had not retired at the exit.
  EXPECT_GE(instructions, json.at("instret").get<uint64_t>());
  EXPECT_LE(instructions, json.at("instret").get<uint64_t>() + 8);
  EXPECT_GT(cycles["_start"], 0u);  // crt0: an assembly label without a size
  for (const char* kernel : {"transform", "clip"}) {
    unsigned long printed = 0;
    const size_t at = r.out.find(std::string("bench ") + kernel + " cycles ");
    ASSERT_NE(at, std::string::npos) << r.out;
    ASSERT_EQ(std::sscanf(r.out.c_str() + at + std::string("bench ").size() + std::string(kernel).size(), " cycles %lu",
                          &printed),
              1);
    const std::string fn = std::string("htx::bench::") + kernel + "_run(unsigned int)";
    ASSERT_TRUE(cycles.count(fn)) << fn << " missing in " << json.at("hotspots").dump();
    EXPECT_LE(cycles[fn], printed) << fn;
    EXPECT_GE(cycles[fn] + 100, printed) << fn;
  }
}

}  // namespace
