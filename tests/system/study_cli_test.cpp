// `htx study` end to end: a quick sweep timed on the Verilated GPU writes its CSV (every point's RTL
// frame equal to the model's), its summary and its chart; bad arguments are refused clearly.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) fields.push_back(std::exchange(field, ""));
    else field += c;
  }
  fields.push_back(field);
  return fields;
}

TEST(SystemStudyCli, QuickRatioSweepOnTheRtl) {
  const std::string dir = ::testing::TempDir() + "htx_study_cli";
  std::filesystem::remove_all(dir);
  const auto r = htx::test::run_program({HTX_BIN, "study", "ratio", "--quick", "--out-dir", dir}, 300s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("clocks from rtl"), std::string::npos) << r.out;

  std::ifstream csv(dir + "/study.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = split(line);
  const auto column = [&](const std::string& name) {
    return static_cast<size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const size_t mismatch = column("mismatch"), clocks = column("clocks"), method = column("method"),
               bound_ratio = column("bound_ratio");
  // Every column indexed below is in the header (column() gives header.size() for a missing one).
  ASSERT_LT(mismatch, header.size()) << line;
  ASSERT_LT(clocks, header.size()) << line;
  ASSERT_LT(method, header.size()) << line;
  ASSERT_LT(bound_ratio, header.size()) << line;
  size_t rows = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = split(line);
    ASSERT_EQ(f.size(), header.size()) << line;
    EXPECT_EQ(f[mismatch], "0") << line;  // the RTL drew the model's frame
    EXPECT_GT(std::stoull(f[clocks]), 1000u) << line;
    EXPECT_NE(f[method], "quadratic");  // the RTL builds no QUADRATIC: such points are left out
    // Every pixel within the predicted bound of the triangle that drew it.
    EXPECT_GE(std::stod(f[bound_ratio]), 0.0) << line;
    EXPECT_LE(std::stod(f[bound_ratio]), 1.0) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 15u);  // 3 ratios x 5 methods
  std::ifstream md_file(dir + "/study.md");
  std::stringstream md;
  md << md_file.rdbuf();
  // A quick run says so, first; each breakdown says whether the bound held.
  EXPECT_EQ(md.str().rfind("**A quick run (`--quick`)", 0), 0u) << md.str();
  EXPECT_NE(md.str().find("| worst error / bound | bound holds | finite |"), std::string::npos) << md.str();
  EXPECT_GT(std::filesystem::file_size(dir + "/study_ratio.svg"), 1000u);
}

// A point where no pixel was compared reports errors of 0, which is no result: at 1x1 the pixel
// centre falls between `wrap`'s panels, and the run lists the points in study.md and fails.
TEST(SystemStudyCli, APointWithNothingComparedFailsTheRun) {
  const std::string dir = ::testing::TempDir() + "htx_study_cli_nothing";
  std::filesystem::remove_all(dir);
  const auto r = htx::test::run_program({HTX_BIN, "study", "offset", "--quick", "--clocks", "estimate", "--size",
                                         "1x1", "--out-dir", dir, "--no-charts"},
                                        120s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("15 point(s) whose errors are not a clean measurement"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("NOT A CLEAN MEASUREMENT: no pixel compared"), std::string::npos) << r.out;
  std::ifstream md_file(dir + "/study.md");
  std::stringstream md;
  md << md_file.rdbuf();
  EXPECT_NE(md.str().find("- offset `wrap:offset=16384` divfree: no pixel compared\n"), std::string::npos)
      << md.str();
}

TEST(SystemStudyCli, RefusesUnknownSweepsAndClockSources) {
  const auto sweep = htx::test::run_program({HTX_BIN, "study", "nosuch", "--out-dir", ::testing::TempDir()}, 60s);
  EXPECT_NE(sweep.status, 0);
  EXPECT_NE(sweep.err.find("nosuch"), std::string::npos) << sweep.err;
  const auto clocks =
      htx::test::run_program({HTX_BIN, "study", "ratio", "--clocks", "sundial", "--out-dir", ::testing::TempDir()}, 60s);
  EXPECT_EQ(clocks.status, 2);  // the option parser's refusal, before any work
  EXPECT_NE(clocks.err.find("--clocks: sundial not in {rtl,estimate}"), std::string::npos) << clocks.err;
  const auto config =
      htx::test::run_program({HTX_BIN, "study", "ratio", "--config", "huge", "--out-dir", ::testing::TempDir()}, 60s);
  EXPECT_EQ(config.status, 2);
  EXPECT_NE(config.err.find("--config: huge not in {full,icebreaker}"), std::string::npos) << config.err;
}

// A sweep named twice runs once; an output directory with a quote and a space in its name is only
// a name (gnuplot runs there without a shell).
TEST(SystemStudyCli, RepeatedSweepRunsOnceAndAnyDirectoryNameDraws) {
  const std::string dir = ::testing::TempDir() + "htx study it's here";
  std::filesystem::remove_all(dir);
  const auto r = htx::test::run_program({HTX_BIN, "study", "ratio", "ratio", "--quick", "--clocks", "estimate", "--size",
                                         "32x24", "--out-dir", dir},
                                        120s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream csv(dir + "/study.csv");
  std::string line;
  size_t rows = 0;
  while (std::getline(csv, line)) ++rows;
  const auto once = htx::test::run_program({HTX_BIN, "study", "ratio", "--quick", "--clocks", "estimate", "--size",
                                            "32x24", "--out-dir", dir + "/once", "--no-charts"},
                                           120s);
  ASSERT_EQ(once.status, 0) << once.err;
  std::ifstream csv_once(dir + "/once/study.csv");
  size_t rows_once = 0;
  while (std::getline(csv_once, line)) ++rows_once;
  EXPECT_GT(rows_once, 1u);
  EXPECT_EQ(rows, rows_once);
  EXPECT_GT(std::filesystem::file_size(dir + "/study_ratio.svg"), 1000u) << r.out;
}

// The tables are checked before the points run: a study.csv that is a directory costs nothing.
TEST(SystemStudyCli, ATableThatCannotBeWrittenIsRefusedBeforeTheRun) {
  const std::string dir = ::testing::TempDir() + "htx_study_table_dir";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/study.csv");
  const auto r = htx::test::run_program({HTX_BIN, "study", "ratio", "--quick", "--clocks", "estimate", "--size",
                                         "32x24", "--out-dir", dir, "--no-charts"},
                                        120s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("study.csv: is a directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("[1/"), std::string::npos) << r.out;  // no point ran
}

}  // namespace
