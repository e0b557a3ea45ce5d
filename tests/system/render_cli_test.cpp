// htx render's board configuration: `--config icebreaker-board` is `icebreaker` with the board
// GPU's methods only (AFFINE, RECIP_LUT). The rtl engine draws it on the Verilated board GPU (the
// design gpu_icebreaker_up5k synthesises) bit for bit with the model; a scene asking for another
// method is refused with a clear error.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + "htx_render_cli_" + name;
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(SystemRenderCli, BoardConfigurationDrawsOnTheBoardGpu) {
  for (const char* method : {"affine", "recip_lut", "auto"}) {
    const std::string png = temp_path(std::string(method) + ".png");
    const std::string metrics = temp_path(std::string(method) + ".json");
    const auto r = htx::test::run_program({HTX_BIN, "render", "floor", "--engine", "rtl", "--config",
                                           "icebreaker-board", "--method", method, "--size", "80x60", "--out",
                                           png, "--metrics", metrics},
                                          120s);
    ASSERT_FALSE(r.timed_out);
    ASSERT_EQ(r.status, 0) << method << ": " << r.err;
    const nlohmann::json j = read_json(metrics);
    EXPECT_EQ(j.at("config"), "icebreaker-board") << method;
    EXPECT_GT(j.at("covered_pixels").get<uint64_t>(), 1000u) << method;
    EXPECT_EQ(j.at("model_mismatch_pixels"), 0) << method;
  }
}

TEST(SystemRenderCli, BoardConfigurationRefusesAMethodItDoesNotBuild) {
  for (const char* engine : {"model", "rtl"}) {
    const auto r = htx::test::run_program({HTX_BIN, "render", "floor", "--engine", engine, "--config",
                                           "icebreaker-board", "--method", "recip_nr", "--size", "80x60",
                                           "--out", temp_path("refused.png")},
                                          120s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, 1) << engine;
    EXPECT_NE(r.err.find("recip_nr is not built"), std::string::npos) << engine << ": " << r.err;
  }
}

}  // namespace
