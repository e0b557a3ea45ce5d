// htx render's board configuration: `--config icebreaker-board` is `icebreaker` with the board
// GPU's methods only (AFFINE, RECIP_LUT). The rtl engine draws it on the Verilated board GPU (the
// design gpu_icebreaker_up5k synthesises) bit for bit with the model; a scene asking for another
// method is refused with a clear error. An output in a directory that does not exist is refused
// before anything is rendered or written.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

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

// The rtl engine's texel-coordinate errors: the Verilated GPU has no probe, but where its frame is
// the model's on the same records (colour and depth at every pixel) the model's probe is its
// frame's, and the figures are those `--engine model` reports for the same options; so are
// DIVFREE's per-pixel step counts, which only the model keeps (CNT_DIVFREE_STEPS is a total).
TEST(SystemRenderCli, RtlEngineTakesTheModelsProbeWhereItsFrameIsTheModels) {
  for (const char* method : {"recip_lut", "divfree"}) {
    nlohmann::json by_engine[2];
    for (int e = 0; e < 2; ++e) {
      const std::string engine = e == 0 ? "rtl" : "model";
      const std::string metrics = temp_path("probe_" + engine + "_" + method + ".json");
      const auto r = htx::test::run_program({HTX_BIN, "render", "wsweep:r=10", "--engine", engine, "--config",
                                             "icebreaker", "--method", method, "--size", "80x60", "--out",
                                             temp_path("probe_" + engine + ".png"), "--metrics", metrics},
                                            120s);
      ASSERT_FALSE(r.timed_out);
      ASSERT_EQ(r.status, 0) << engine << " " << method << ": " << r.err;
      by_engine[e] = read_json(metrics);
    }
    const nlohmann::json& rtl = by_engine[0];
    const nlohmann::json& model = by_engine[1];
    ASSERT_EQ(rtl.at("model_mismatch_pixels"), 0) << method;
    EXPECT_EQ(rtl.at("probe"), "model") << method;
    EXPECT_GT(rtl.at("compared_pixels").get<uint64_t>(), 1000u) << method;
    EXPECT_GT(rtl.at("max_texel_error").get<double>(), 0.0) << method;  // the method's error, not a perfect probe
    for (const char* key : {"max_texel_error", "rms_texel_error", "p999_texel_error", "compared_pixels",
                            "coverage_diff_pixels", "surface_diff_pixels", "divfree_max_steps", "divfree_mean_steps",
                            "divfree_cap_hits"})
      EXPECT_EQ(rtl.at(key), model.at(key)) << method << " " << key;
    if (std::string(method) == "divfree") {
      EXPECT_GT(rtl.at("divfree_max_steps").get<uint64_t>(), 0u);
      EXPECT_GT(rtl.at("divfree_mean_steps").get<double>(), 0.0);
      EXPECT_EQ(rtl.at("divfree_steps_total"), rtl.at("model_divfree_steps_total"));
    }
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
    EXPECT_NE(r.err.find("recip_nr is not built in configuration icebreaker-board"), std::string::npos)
        << engine << ": " << r.err;
    // Without --method, a scene whose triangles ask for such a method: the message says so.
    const auto own = htx::test::run_program({HTX_BIN, "render", "bigtri", "--engine", engine, "--config",
                                             "icebreaker-board", "--size", "80x60", "--out", temp_path("refused.png")},
                                            120s);
    EXPECT_EQ(own.status, 1) << engine;
    EXPECT_NE(own.err.find("recip_nr is not built in configuration icebreaker-board (the scene's triangles ask "
                           "for it; --method auto picks a built one)"),
              std::string::npos)
        << engine << ": " << own.err;
  }
}

TEST(SystemRenderCli, OutputsInAMissingDirectoryAreRefusedBeforeRendering) {
  const std::string missing = temp_path("no_such_dir");
  const std::string png = temp_path("before_metrics.png");
  std::filesystem::remove(png);
  for (const auto& [option, path] : {std::pair<std::string, std::string>{"--out", missing + "/x.png"},
                                     std::pair<std::string, std::string>{"--metrics", missing + "/m.json"}}) {
    std::vector<std::string> args = {HTX_BIN, "render", "cube", "--size", "32x24"};
    if (option == "--out") {
      args.insert(args.end(), {"--out", path});
    } else {
      args.insert(args.end(), {"--out", png, "--metrics", path});
    }
    const auto r = htx::test::run_program(args, 60s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, 1) << option;
    EXPECT_NE(r.err.find(path + ": no directory " + missing + " to write it in"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("rendered"), std::string::npos) << option << ": rendered first: " << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(png)) << "the PNG was written before the metrics were refused";
}

// A write that fails (/dev/full: no space left) is an error, for the PNG and for the metrics.
TEST(SystemRenderCli, WriteErrorsAreErrors) {
  for (const std::vector<std::string>& outputs :
       {std::vector<std::string>{"--out", "/dev/full"},
        std::vector<std::string>{"--out", temp_path("full_metrics.png"), "--metrics", "/dev/full"}}) {
    std::vector<std::string> args = {HTX_BIN, "render", "cube", "--engine", "model", "--size", "32x24"};
    args.insert(args.end(), outputs.begin(), outputs.end());
    const auto r = htx::test::run_program(args, 60s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, 1) << outputs.back();
    EXPECT_NE(r.err.find("cannot write '/dev/full': No space left on device"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("-> /dev/full"), std::string::npos) << "reported as written: " << r.out;
  }
}

// An output that is a directory, two outputs that are one file, an output that cannot be written,
// or one that is the command's standard output are refused before rendering.
TEST(SystemRenderCli, OutputsThatCannotBeWrittenAreRefusedBeforeRendering) {
  const std::string dir = temp_path("a_dir");
  std::filesystem::create_directories(dir);
  const std::string png = temp_path("one_file.png");
  std::filesystem::remove(png);
  const struct {
    std::vector<std::string> outputs;
    std::string message;
  } cases[] = {
      {{"--out", dir}, dir + ": is a directory, not a file to write"},
      {{"--out", png, "--metrics", dir}, dir + ": is a directory, not a file to write"},
      {{"--out", png, "--metrics", ::testing::TempDir() + "./htx_render_cli_one_file.png"}, "two outputs to one file"},
      // /proc takes no new files; standard output carries the report lines, which would corrupt
      // an image there.
      {{"--out", "/proc/htx_no.png"}, "/proc/htx_no.png: cannot be written ("},
      {{"--out", png, "--metrics", "/proc/htx_no.json"}, "/proc/htx_no.json: cannot be written ("},
      {{"--out", "/dev/stdout"}, "/dev/stdout: is this command's standard output"},
      {{"--out", png, "--metrics", "/dev/stdout"}, "/dev/stdout: is this command's standard output"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {HTX_BIN, "render", "cube", "--engine", "model", "--size", "32x24"};
    args.insert(args.end(), c.outputs.begin(), c.outputs.end());
    const auto r = htx::test::run_program(args, 60s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, 1) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("rendered"), std::string::npos) << "rendered first: " << r.out;
    EXPECT_FALSE(std::filesystem::exists(png)) << c.message << ": " << png << " was written or left behind";
  }
  // Not refused: /dev/null as the output while standard output is /dev/null too (a device is no
  // clash), and a link to a file yet to be made (its writer makes the file).
  const auto null = htx::test::run_program(
      {"/bin/sh", "-c", std::string(HTX_BIN) + " render cube --engine model --size 32x24 --out /dev/null > /dev/null"},
      60s);
  EXPECT_EQ(null.status, 0) << null.err;
  const std::string link = temp_path("link_out.png"), target = temp_path("link_target.png");
  std::filesystem::remove(link);
  std::filesystem::remove(target);
  std::filesystem::create_symlink(target, link);
  const auto linked =
      htx::test::run_program({HTX_BIN, "render", "cube", "--engine", "model", "--size", "32x24", "--out", link}, 60s);
  EXPECT_EQ(linked.status, 0) << linked.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(target));
}

// Options that belong to other engines are refused rather than ignored; values outside what an
// option takes are the option parser's refusals (status 2).
TEST(SystemRenderCli, OptionsOfOtherEnginesAndValuesOutOfRangeAreRefused) {
  const struct {
    std::vector<std::string> options;
    int status;
    std::string message;
  } cases[] = {
      {{"--engine", "model", "--baud", "9600"}, 1, "--baud is for --engine board"},
      {{"--engine", "ref", "--timeout", "5"}, 1, "--timeout is for --engine soc and board"},
      {{"--engine", "ref", "--method", "affine"}, 1, "--method: ref draws every triangle exactly"},
      {{"--engine", "model", "--port", "/dev/null"}, 1, "--port is for --engine board"},
      {{"--engine", "model", "--firmware", "x.elf"}, 1, "--firmware is for --engine soc"},
      {{"--engine", "soc", "--baud", "9600"}, 1, "--baud is for --engine board"},
      {{"--engine", "board", "--port", "/dev/null", "--fast-baud", "500000"}, 1,
       "--fast-baud 500000: want 9600, 19200"},
      {{"--tolerance", "nan"}, 2, "--tolerance: want a finite number > 0, not nan"},
      {{"--tolerance", "inf"}, 2, "--tolerance: want a finite number > 0, not inf"},
      {{"--engine", "soc", "--timeout", "nan"}, 2, "--timeout: want seconds from 0.001 to 86400, not nan"},
      {{"--engine", "soc", "--timeout", "1e300"}, 2, "--timeout: want seconds from 0.001 to 86400, not 1e300"},
      {{"--config", "icebreaker-boards"}, 2, "--config: icebreaker-boards not in {full,icebreaker,icebreaker-board}"},
      {{"--engine", "board", "--port", "/dev/null", "--fast-baud", "0"}, 2, "--fast-baud: Value 0 not in range 1 to 3000000"},
      // Sizes are two decimal numbers in range (sscanf's %d wrapped 4294967306 to 10).
      {{"--size", "4294967306x10"}, 1, "--size '4294967306x10': want WxH with 1 <= W, H <= 4096"},
      {{"--size", "+10x+10"}, 1, "--size '+10x+10': want WxH"},
      {{"--size", "10x10 "}, 1, "--size '10x10 ': want WxH"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {HTX_BIN, "render", "cube", "--out", temp_path("refused_option.png")};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const auto r = htx::test::run_program(args, 60s);
    ASSERT_FALSE(r.timed_out);
    EXPECT_EQ(r.status, c.status) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}

}  // namespace

namespace {

// `--method auto` says what AUTO gave the triangles (a line, and the metrics' "auto" object): on
// `icebreaker` most of `floor`'s are small enough that choosing would not pay and get RECIP_NR
// without comparing (docs/auto.md); `full` prices the choice at nothing and compares every one; a
// draw without AUTO has no such object.
TEST(SystemRenderCli, AutoReportsWhatItGaveTheTriangles) {
  std::map<std::string, nlohmann::json> by_config;
  for (const char* config : {"icebreaker", "full"}) {
    const std::string metrics = temp_path(std::string("auto_") + config + ".json");
    const auto r = htx::test::run_program({HTX_BIN, "render", "floor", "--engine", "model", "--config", config,
                                           "--method", "auto", "--tolerance", "0.0625", "--size", "160x120",
                                           "--out", temp_path(std::string("auto_") + config + ".png"), "--metrics",
                                           metrics},
                                          60s);
    ASSERT_FALSE(r.timed_out);
    ASSERT_EQ(r.status, 0) << config << ": " << r.err;
    EXPECT_NE(r.out.find("auto: 116 triangles at 0.0625 texel: "), std::string::npos) << r.out;
    const nlohmann::json a = read_json(metrics).at("auto");
    EXPECT_EQ(a.at("triangles"), 116) << config;
    uint64_t sum = 0;
    for (const auto& [name, count] : a.at("methods").items()) sum += count.get<uint64_t>();
    EXPECT_EQ(sum, 116u) << a.dump();
    EXPECT_EQ(a.at("not_within"), 0) << a.dump();
    by_config[config] = a;
  }
  const nlohmann::json& ice = by_config["icebreaker"];
  EXPECT_GT(ice.at("skipped").get<uint64_t>(), 100u) << ice.dump();
  EXPECT_LE(ice.at("skipped").get<uint64_t>(), ice.at("methods").at("recip_nr").get<uint64_t>()) << ice.dump();
  EXPECT_EQ(by_config["full"].at("skipped"), 0) << by_config["full"].dump();

  const std::string metrics = temp_path("no_auto.json");
  const auto r = htx::test::run_program({HTX_BIN, "render", "floor", "--engine", "model", "--size", "80x60", "--out",
                                         temp_path("no_auto.png"), "--metrics", metrics},
                                        60s);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("auto:"), std::string::npos) << r.out;
  EXPECT_FALSE(read_json(metrics).contains("auto"));
}

// An output over one of the command's own input files (the OBJ, its material library, its
// texture) is refused before anything is drawn, and the file stays as it was.
TEST(SystemRenderCli, AnOutputOverTheScenesOwnFilesIsRefused) {
  namespace fs = std::filesystem;
  const fs::path dir = temp_path("own_files");
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const char* name : {"quad.obj", "quad.mtl", "checker8x16.png"})
    fs::copy_file(fs::path(HTX_TEST_DATA_DIR) / name, dir / name);
  const std::string obj = (dir / "quad.obj").string();
  for (const char* name : {"quad.obj", "quad.mtl", "checker8x16.png"}) {
    const std::string file = (dir / name).string();
    const auto size = fs::file_size(file);
    for (const char* option : {"--out", "--metrics"}) {
      std::vector<std::string> args = {HTX_BIN, "render", obj, "--engine", "model"};
      if (std::string(option) == "--out") {
        args.insert(args.end(), {"--out", file});
      } else {
        args.insert(args.end(), {"--out", (dir / "frame.png").string(), "--metrics", file});
      }
      const auto r = htx::test::run_program(args, 60s);
      ASSERT_FALSE(r.timed_out);
      EXPECT_EQ(r.status, 1) << name << " " << option;
      EXPECT_NE(r.err.find("writing it would destroy it"), std::string::npos) << r.err;
      EXPECT_EQ(fs::file_size(file), size) << name << " " << option;
    }
  }
  EXPECT_FALSE(fs::exists(dir / "frame.png"));
}

// A triangle the vertex-record encoder refuses (texture coordinate 30,000 on an 8 x 16 texture:
// u beyond the record's range) draws nothing on model and rtl, as the firmware does not send it;
// htx render says how many, in its line, on standard error and in the metrics (`dropped`), as the
// soc engine reports the console's. Until 2026-12-06 they vanished without a word.
TEST(SystemRenderCli, TrianglesTheEncoderRefusesAreCountedAsDropped) {
  namespace fs = std::filesystem;
  const fs::path dir = temp_path("dropped");
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(fs::path(HTX_TEST_DATA_DIR) / "checker8x16.png", dir / "checker8x16.png");
  std::ofstream(dir / "far.mtl") << "newmtl m\nKd 1 1 1\nmap_Kd checker8x16.png\n";
  std::ofstream(dir / "far.obj") << "mtllib far.mtl\nv 0 0 -3\nv 1 0 -3\nv 0 1 -3\nv 1 1 -3\n"
                                 << "vt 0 0\nvt 30000 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\nf 2/1 4/1 3/1\n";
  for (const char* engine : {"model", "rtl", "ref"}) {
    const std::string metrics = (dir / (std::string(engine) + ".json")).string();
    const auto r = htx::test::run_program({HTX_BIN, "render", (dir / "far.obj").string(), "--engine", engine, "--size",
                                           "80x60", "--out", (dir / "far.png").string(), "--metrics", metrics},
                                          120s);
    ASSERT_FALSE(r.timed_out);
    ASSERT_EQ(r.status, 0) << engine << ": " << r.err;
    const bool ref = std::string(engine) == "ref";  // draws every triangle exactly
    EXPECT_EQ(r.out.find("(2 triangles, 1 dropped, 80x60)") != std::string::npos, !ref) << engine << ": " << r.out;
    EXPECT_EQ(r.err.find(std::string(engine) + " dropped 1 triangles: the vertex-record format cannot hold them") !=
                  std::string::npos,
              !ref)
        << engine << ": " << r.err;
    const nlohmann::json j = read_json(metrics);
    if (ref)
      EXPECT_FALSE(j.contains("dropped"));
    else
      EXPECT_EQ(j.at("dropped"), 1) << engine;
  }
  fs::remove_all(dir);
}

// Words htx cannot use are refused with a message that says what is wrong: an unknown command, an
// empty output path, --tolerance beside a method that has none, parameters on an OBJ file, a
// directory given as an OBJ; and a standard output that cannot be written is status 1.
TEST(SystemRenderCli, MistakesAreNamed) {
  auto r = htx::test::run_program({HTX_BIN, "bogus"}, 60s);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no command 'bogus'"), std::string::npos) << r.err;
  r = htx::test::run_program({HTX_BIN, "render", "cube", "--out", ""}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--out: an empty path"), std::string::npos) << r.err;
  r = htx::test::run_program({HTX_BIN, "render", "cube", "--engine", "model", "--method", "affine", "--tolerance",
                              "0.5", "--out", temp_path("tolerance.png")},
                             60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--tolerance is AUTO's"), std::string::npos) << r.err;
  r = htx::test::run_program({HTX_BIN, "render", "cube", "--engine", "model", "--method", "auto", "--tolerance",
                              "0.5", "--out", temp_path("tolerance.png")},
                             60s);
  EXPECT_EQ(r.status, 0) << r.err;
  r = htx::test::run_program(
      {HTX_BIN, "render", std::string(HTX_TEST_DATA_DIR) + "/quad.obj:yaw=3", "--out", temp_path("params.png")}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("an OBJ file takes no parameters"), std::string::npos) << r.err;
  const std::string dir_obj = temp_path("a_dir.obj");
  std::filesystem::create_directories(dir_obj);
  r = htx::test::run_program({HTX_BIN, "render", dir_obj, "--out", temp_path("dir_obj.png")}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("a_dir.obj': not a file"), std::string::npos) << r.err;
  r = htx::test::run_program({"/bin/sh", "-c", std::string("exec '") + HTX_BIN + "' scenes >/dev/full"}, 60s);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("htx scenes: standard output could not be written"), std::string::npos) << r.err;
}

// `--engine soc` with a firmware that is not the console: the pseudo-terminal closes as the SoC's
// run ends, and the error says how it ended (here an exit after a few thousand clocks). Before,
// the console's silence was reported alone, after the whole --timeout.
TEST(SystemRenderCli, ASocThatStoppedSaysHowWhenTheConsoleIsQuiet) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = htx::test::run_program({HTX_BIN, "render", "cube", "--engine", "soc", "--firmware", HTX_SIM_CALLS_ELF,
                                         "--timeout", "100", "--out", temp_path("quiet.png")},
                                        60s);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 50s);  // not the timeout
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("; the simulated SoC had stopped after "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" clocks: tohost with code 0"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(temp_path("quiet.png")));
}

}  // namespace
