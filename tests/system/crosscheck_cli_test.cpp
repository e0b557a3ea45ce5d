// `htx crosscheck`: random renders drawn from a seed, each by the model and by the Verilated GPU
// (or the console firmware on the simulated SoC), compared pixel for pixel. A fixed seed's cases
// agree on both; the cases are a function of the seed and their number alone, drawn within the
// ranges the scenes list, and cover every scene and configuration; a scene over the triangle limit
// is skipped; bad arguments are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "htx/model/scenes.hpp"
#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// NAME[:key=value,...]: NAME a built-in scene, each key one of its parameters, given once, each
// value a decimal number within the parameter's listed range (an integer where it must be).
bool params_within_listed_ranges(const std::string& spec) {
  const size_t colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  const htx::SceneInfo* scene = nullptr;
  for (const htx::SceneInfo& s : htx::builtin_scenes())
    if (s.name == name) scene = &s;
  if (!scene) return false;
  if (colon == std::string::npos) return true;
  std::set<std::string> seen;
  std::istringstream pairs(spec.substr(colon + 1));
  for (std::string pair; std::getline(pairs, pair, ',');) {
    const size_t eq = pair.find('=');
    if (eq == std::string::npos) return false;
    const std::string key = pair.substr(0, eq), text = pair.substr(eq + 1);
    if (!seen.insert(key).second) return false;
    const htx::SceneParamInfo* p = nullptr;
    for (const htx::SceneParamInfo& q : scene->params)
      if (q.key == key) p = &q;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (!p || text.empty() || *end != '\0' || v < p->min || v > p->max || (p->integer && v != std::floor(v)))
      return false;
  }
  return true;
}

TEST(SystemCrosscheckCli, AFixedSeedsCasesAgreeOnTheModelAndTheRtl) {
  const auto r = htx::test::run_program({HTX_BIN, "crosscheck", "--seed", "20261207", "--count", "24"}, 110s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m,
                                std::regex(R"(crosscheck rtl seed 20261207: 24 cases, (\d+) equal, 0 different, (\d+) )"
                                           R"(refused alike, 0 refused by one engine only, 0 skipped)")))
      << r.out;
  // Most cases draw something (a refusal both engines share compares nothing).
  EXPECT_GE(std::stoi(m[1]), 16) << r.out;
  EXPECT_EQ(std::stoi(m[1]) + std::stoi(m[2]), 24);
  for (int i = 0; i < 24; ++i) EXPECT_NE(r.out.find("[" + std::to_string(i) + "] "), std::string::npos) << i;
}

// The console firmware on the simulated SoC against the model drawing the console's own triangles
// (each case a fresh SoC, some 6 s).
TEST(SystemCrosscheckCli, ASeedsCasesOnTheSocAgreeWithTheModel) {
  const auto r =
      htx::test::run_program({HTX_BIN, "crosscheck", "--engine", "soc", "--seed", "3", "--count", "3"}, 110s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m,
                                std::regex(R"(crosscheck soc seed 3: 3 cases, (\d+) equal, 0 different, \d+ refused )"
                                           R"(alike, 0 refused by one engine only, 0 skipped)")))
      << r.out;
  EXPECT_GE(std::stoi(m[1]), 2) << r.out;
  EXPECT_NE(r.out.find("sent, the simulated SoC, "), std::string::npos) << r.out;
}

// A scene over --max-triangles is skipped, and counted so.
TEST(SystemCrosscheckCli, ScenesOverTheTriangleLimitAreSkipped) {
  const auto r = htx::test::run_program(
      {HTX_BIN, "crosscheck", "--seed", "20261207", "--count", "4", "--max-triangles", "1"}, 60s);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("(over --max-triangles 1)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 cases, 0 equal, 0 different"), std::string::npos) << r.out;
}

TEST(SystemCrosscheckCli, CasesAreTheSeedsAndNumbersAloneAndWithinTheListedRanges) {
  const auto list = [](const std::vector<std::string>& extra) {
    std::vector<std::string> argv = {HTX_BIN, "crosscheck", "--list"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    const auto r = htx::test::run_program(argv, 30s);
    EXPECT_EQ(r.status, 0) << r.err;
    return lines_of(r.out);
  };
  const std::vector<std::string> cases = list({"--seed", "5", "--count", "120"});
  ASSERT_EQ(cases.size(), 120u);
  EXPECT_EQ(list({"--seed", "5", "--count", "120"}), cases);
  const std::vector<std::string> later = list({"--seed", "5", "--first", "110", "--count", "10"});
  EXPECT_EQ(later, std::vector<std::string>(cases.begin() + 110, cases.end()));
  EXPECT_NE(list({"--seed", "6", "--count", "120"}), cases);

  // "N: SCENE --config C [--method M] [--filter F] [--tolerance T] [--untextured] --size WxH"
  const std::regex line(R"((\d+): (\S+) --config (\S+)( --method \S+)?( --filter \S+)?( --tolerance \S+)?)"
                        R"(( --untextured)? --size (\d+)x(\d+))");
  std::set<std::string> scenes, configs;
  for (const std::string& text : cases) {
    std::smatch m;
    ASSERT_TRUE(std::regex_match(text, m, line)) << text;
    // Every parameter is one its scene lists, within its range (an integer where it must be). The
    // scenes are not built here (some have 10^5 triangles, minutes under the sanitizers); the
    // drawing tests above build theirs, and crosscheck stops with an error on a spec refused.
    EXPECT_TRUE(params_within_listed_ranges(m[2])) << text;
    scenes.insert(m[2].str().substr(0, m[2].str().find(':')));
    configs.insert(m[3]);
    EXPECT_GE(std::stoi(m[8]), 1);
    EXPECT_LE(std::stoi(m[8]), 400);
    EXPECT_GE(std::stoi(m[9]), 1);
    EXPECT_LE(std::stoi(m[9]), 300);
  }
  EXPECT_EQ(configs, (std::set<std::string>{"full", "icebreaker", "icebreaker-board"}));
  std::set<std::string> every_scene;
  for (const htx::SceneInfo& s : htx::builtin_scenes()) every_scene.insert(s.name);
  EXPECT_EQ(scenes, every_scene);

  // On the SoC: its GPU's configuration, its screen, and tolerances of 1/N texel (a power of two).
  const std::vector<std::string> soc = list({"--engine", "soc", "--seed", "5", "--count", "60"});
  ASSERT_EQ(soc.size(), 60u);
  const std::regex soc_line(R"(\d+: \S+ --config icebreaker( --method \S+)?( --filter \S+)?)"
                            R"(( --tolerance (1|0\.5|0\.25|0\.125|0\.0625|0\.03125|0\.015625|0\.0078125|0\.00390625))?)"
                            R"(( --untextured)? --size 160x120)");
  for (const std::string& text : soc) EXPECT_TRUE(std::regex_match(text, soc_line)) << text;
}

TEST(SystemCrosscheckCli, BadArgumentsAreRefused) {
  auto r = htx::test::run_program({HTX_BIN, "crosscheck", "--count", "0"}, 30s);
  EXPECT_EQ(r.status, 2) << r.err;
  r = htx::test::run_program({HTX_BIN, "crosscheck", "--first", "18446744073709551615", "--count", "2"}, 30s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("past the last case number"), std::string::npos) << r.err;
  r = htx::test::run_program({HTX_BIN, "crosscheck", "--minutes", "-1"}, 30s);
  EXPECT_EQ(r.status, 2) << r.err;
  // An output directory that cannot be made or written is refused before any case runs.
  r = htx::test::run_program({HTX_BIN, "crosscheck", "--out-dir", "/proc/htx_no_such_dir"}, 30s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--out-dir /proc/htx_no_such_dir: cannot be made"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("[0]"), std::string::npos) << r.out;
  r = htx::test::run_program({HTX_BIN, "crosscheck", "--out-dir", "/proc/self"}, 30s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot be written"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("[0]"), std::string::npos) << r.out;
}

}  // namespace
