// htx crosscheck: random renders drawn from a seed, each drawn by the model and by the Verilated
// GPU (the rtl engine) with the same configuration, compared pixel for pixel (colour and depth);
// or (--engine soc) by the console firmware on the simulated SoC, against the model drawing the
// console's own triangles.
// The RTL must match the model bit for bit (and count as it counts); a case where they differ, or where one engine
// refuses what the other draws, is a bug in one of them, and its line gives the `htx render` command that makes it
// again.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "crosscheck_cases.hpp"
#include "htx/model/scenes.hpp"
#if __has_include("htx/rtl/raster_engine.hpp")
#include "console_scene.hpp"
#include "htx/fw/auto_scene.h"
#include "htx/model/geometry.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/model.hpp"
#include "htx/rtl/raster_engine.hpp"
#include "output_path.hpp"
#include "render_args.hpp"
#include "render_setup.hpp"
#define HTX_HAVE_RTL_ENGINE 1
#endif

namespace htx {

namespace {

struct CrosscheckArgs {
  uint64_t seed = 1;
  uint64_t first = 0;
  uint32_t count = 50;
  double minutes = 0;  // 0: no time limit
  std::string out_dir;
  bool list = false;
  std::string engine = "rtl";
  uint32_t max_triangles = 0;  // 0: the engine's default (kSocMaxTriangles on soc, no limit on rtl)
};

// soc: a case's scene above this many triangles is skipped unless --max-triangles says otherwise
// (the SoC simulation runs some 2.5 M clocks a second, and the CPU spends thousands a triangle).
constexpr uint32_t kSocMaxTriangles = 2000;

std::string case_label(const CrosscheckCase& c) {
  return c.scene + " " + crosscheck_case_options(c);
}

#ifdef HTX_HAVE_RTL_ENGINE

struct Tally {
  uint64_t equal = 0, different = 0, refused_alike = 0, refused_by_one = 0, skipped = 0;
};

// One engine's frame, or its refusal's message.
struct Drawn {
  std::optional<Frame> frame;
  std::string error;
};

template <class Draw>
Drawn draw_with(Draw draw) {
  Drawn d;
  try {
    d.frame = draw();
  } catch (const std::exception& e) {
    d.error = e.what();
  }
  return d;
}

// The case as `htx render`'s arguments on `engine` (its tolerance read as htx render reads it).
RenderArgs render_args_of(const CrosscheckCase& c, const std::string& engine) {
  RenderArgs a;
  a.scene = c.scene;
  a.engine = engine;
  a.config = c.config;
  a.size = std::to_string(c.width) + "x" + std::to_string(c.height);
  a.method = c.method;
  a.filter = c.filter;
  a.untextured = c.untextured;
  if (!c.tolerance.empty()) a.tolerance = std::stod(c.tolerance);
  return a;
}

// --out-dir's two frames of a case that differs: caseN_model.png and caseN_<engine>.png.
void write_frames(const std::string& out_dir, uint64_t index, const CrosscheckCase& c,
                  const std::vector<uint16_t>& model, const std::string& engine, const std::vector<uint16_t>& other) {
  if (out_dir.empty()) return;
  const std::string stem = out_dir + "/case" + std::to_string(index);
  write_png(stem + "_model.png", image_from_rgb565(c.width, c.height, model));
  write_png(stem + "_" + engine + ".png", image_from_rgb565(c.width, c.height, other));
  std::cout << "    frames -> " << stem << "_model.png, " << stem << "_" << engine << ".png" << std::endl;
}

// Runs a case and says what came of it on one line (the case itself is already printed).
void run_case(uint64_t index, const CrosscheckCase& c, uint32_t max_triangles, const std::string& out_dir,
              Tally& tally) {
  Scene scene;
  try {
    scene = load_scene(c.scene);
  } catch (const std::exception& e) {
    // Cases are drawn within the ranges the scenes list, so this is crosscheck's own bug.
    throw std::logic_error("case " + std::to_string(index) + ": scene '" + c.scene +
                           "' was refused, but its parameters were drawn from their listed ranges: " + e.what());
  }
  // As htx render prepares it (render_setup.hpp), with the configuration the RTL builds for both.
  const ModelConfig config = named_config(c.config, rtl_config);
  ScreenScene screen;
  try {
    screen = prepare_screen_scene(scene, c.width, c.height);
  } catch (const std::exception& e) {
    ++tally.refused_alike;  // before either engine: htx render refuses it the same for both
    std::cout << "refused before drawing: " << e.what() << std::endl;
    return;
  }
  if (screen.tris.size() > max_triangles) {
    ++tally.skipped;
    std::cout << "skipped: " << screen.tris.size() << " triangles (over --max-triangles " << max_triangles << ")"
              << std::endl;
    return;
  }
  override_triangle_states(screen, c.method, c.filter, c.untextured);
  fw::resolve_auto_methods(screen, config, static_cast<float>(render_args_of(c, "rtl").tolerance));

  RtlStats stats;
  const Drawn model = draw_with([&] { return render_model(screen, config); });
  const Drawn rtl = draw_with([&] { return render_rtl(screen, config, &stats); });
  if (!model.frame && !rtl.frame) {
    ++tally.refused_alike;
    std::cout << "refused by both: " << model.error << std::endl;
    return;
  }
  const std::string again = crosscheck_render_command(c, "rtl", "rtl.png", "rtl.json") +
                            "  (rtl.json's model_mismatch_pixels counts the differing pixels)";
  if (!model.frame || !rtl.frame) {
    ++tally.refused_by_one;
    std::cout << "REFUSED BY ONE ENGINE: " << (model.frame ? "rtl: " + rtl.error : "model: " + model.error)
              << "\n    the other drew it; again: "
              << crosscheck_render_command(c, model.frame ? "rtl" : "model", "x.png") << std::endl;
    return;
  }
  const uint64_t differing = frame_mismatch_pixels(*model.frame, *rtl.frame);
  // The raster unit's counters, which the model keeps too (docs/raster.md).
  const Counters& counted = model.frame->counters;
  std::string counters;
  auto compare = [&counters](const char* name, uint64_t model_count, uint64_t rtl_count) {
    if (model_count != rtl_count)
      counters += std::string(counters.empty() ? "" : ", ") + name + " " + std::to_string(rtl_count) +
                  " (the model's " + std::to_string(model_count) + ")";
  };
  compare("CNT_FRAGMENTS", counted.fragments, stats.covered_pixels);
  compare("CNT_PIXELS", counted.pixels_written, stats.pixels_written);
  compare("CNT_DIVFREE_STEPS", counted.divfree_steps_total, stats.divfree_steps);
  if (differing == 0 && counters.empty()) {
    ++tally.equal;
    std::cout << "equal (" << screen.tris.size() << " triangles, " << stats.pixels_written << " pixels written, "
              << stats.cycles << " clocks)" << std::endl;
    return;
  }
  ++tally.different;
  std::cout << "DIFFERENT: " << differing << " of " << c.width * c.height << " pixels (colour or depth)"
            << (counters.empty() ? "" : "; counters differ: " + counters) << "\n    again: " << again << std::endl;
  write_frames(out_dir, index, c, model.frame->color, "rtl", rtl.frame->color);
}

// The model's own refusal of the case's method and filter (empty: it draws them), for a case the
// console refused. The console refuses a setting its GPU lacks whatever the triangles (`set filter
// trilinear` for an untextured scene too), so the model is asked with the scene textured.
std::string model_refusal(const Scene& scene, const CrosscheckCase& c) {
  ScreenScene screen = console_screen(scene, false);
  override_triangle_states(screen, c.method, c.filter, false);
  const ModelConfig config = named_config(c.config, rtl_config);
  try {
    fw::resolve_auto_methods(screen, config, 1.0f / 64);
    render_model(screen, config);
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

// A case drawn by the console firmware on a fresh simulated SoC, as `htx render --engine soc`
// draws it, against the model drawing the console's own triangles (the firmware's pipeline run on
// the host): the frame and the triangle counts.
void run_soc_case(uint64_t index, const CrosscheckCase& c, uint32_t max_triangles, const std::string& out_dir,
                  Tally& tally) {
  const RenderArgs a = render_args_of(c, "soc");
  ConsoleScene scene;
  try {
    scene = prepare_console_scene(a);
  } catch (const std::invalid_argument& e) {
    ++tally.refused_alike;  // on the host, before the console: htx render refuses it so
    std::cout << "refused before drawing: " << e.what() << std::endl;
    return;
  }
  // The whole scene: the console receives every triangle and transforms it, on screen or not.
  size_t triangles = 0;
  for (const Mesh& mesh : scene.scene.meshes) triangles += mesh.triangles.size();
  if (triangles > max_triangles) {
    ++tally.skipped;
    std::cout << "skipped: " << triangles << " triangles in the scene (over --max-triangles " << max_triangles << ")"
              << std::endl;
    return;
  }
  const std::string again = crosscheck_render_command(c, "soc", "soc.png", "soc.json") +
                            "  (its stderr says why soc.json has no texel errors)";
  ConsoleRun run;
  try {
    run = draw_console_scene(a, scene.draw, true, {});
  } catch (const std::exception& e) {
    const std::string model = model_refusal(scene.scene, c);
    if (!model.empty()) {
      ++tally.refused_alike;
      std::cout << "refused by both: " << e.what() << " (the model: " << model << ")" << std::endl;
    } else {
      ++tally.refused_by_one;
      std::cout << "REFUSED BY ONE ENGINE: the console: " << e.what()
                << "\n    the model draws it; again: " << crosscheck_render_command(c, "soc", "soc.png") << std::endl;
    }
    return;
  }
  std::string disagreement;
  ConsoleModel model;
  try {
    model = console_model_frame(scene.draw, run.caps);
    disagreement = console_model_disagreement(model, run.drawn);
  } catch (const std::exception& e) {
    ++tally.refused_by_one;
    std::cout << "REFUSED BY ONE ENGINE: the model: " << e.what() << "\n    the console drew it; again: " << again
              << std::endl;
    return;
  }
  if (!disagreement.empty()) {
    ++tally.different;
    std::cout << "DIFFERENT: " << disagreement << "\n    again: " << again << std::endl;
    if (model.frame.color.size() == run.drawn.frame.pixels.size())
      write_frames(out_dir, index, c, model.frame.color, "soc", run.drawn.frame.pixels);
    return;
  }
  ++tally.equal;
  std::cout << "equal (" << run.drawn.figures.at("triangles") << " triangles, " << run.drawn.figures.at("sent")
            << " sent, " << run.where << ")" << std::endl;
}

#endif

void run_crosscheck(const CrosscheckArgs& a) {
  if (a.first > UINT64_MAX - a.count) throw std::invalid_argument("--first + --count is past the last case number");
  const CrosscheckEngine engine = a.engine == "soc" ? CrosscheckEngine::Soc : CrosscheckEngine::Rtl;
  const std::vector<SceneInfo>& scenes = builtin_scenes();
  if (a.list) {
    for (uint64_t i = a.first; i < a.first + a.count; ++i)
      std::cout << i << ": " << case_label(draw_crosscheck_case(a.seed, i, scenes, engine)) << "\n";
    return;
  }
#ifdef HTX_HAVE_RTL_ENGINE
  const uint32_t max_triangles = a.max_triangles > 0               ? a.max_triangles
                                 : engine == CrosscheckEngine::Soc ? kSocMaxTriangles
                                                                   : UINT32_MAX;
  // --out-dir made and tried with a first frame's name before any case runs (a sweep is long).
  if (!a.out_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(a.out_dir, error);
    if (error) throw std::runtime_error("--out-dir " + a.out_dir + ": cannot be made (" + error.message() + ")");
    require_output_dir(a.out_dir + "/case" + std::to_string(a.first) + "_model.png");
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed_s = [&t0] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  Tally tally;
  uint64_t run = 0;
  for (uint64_t i = a.first; i < a.first + a.count; ++i) {
    if (a.minutes > 0 && elapsed_s() > a.minutes * 60) {
      std::cout << "time limit (" << a.minutes << " min) reached before case " << i << "\n";
      break;
    }
    const CrosscheckCase c = draw_crosscheck_case(a.seed, i, scenes, engine);
    // Printed before drawing, so that a case that never ends names itself.
    std::cout << "[" << i << "] " << case_label(c) << ": " << std::flush;
    if (engine == CrosscheckEngine::Soc)
      run_soc_case(i, c, max_triangles, a.out_dir, tally);
    else
      run_case(i, c, max_triangles, a.out_dir, tally);
    ++run;
  }
  std::cout << "crosscheck " << a.engine << " seed " << a.seed << ": " << run << " cases, " << tally.equal << " equal, "
            << tally.different << " different, " << tally.refused_alike << " refused alike, " << tally.refused_by_one
            << " refused by one engine only, " << tally.skipped << " skipped (" << static_cast<int64_t>(elapsed_s())
            << " s)\n";
  if (tally.different + tally.refused_by_one > 0)
    throw std::runtime_error(std::to_string(tally.different + tally.refused_by_one) + " case(s) where the " +
                             (engine == CrosscheckEngine::Soc ? "SoC" : "RTL") +
                             " and the model disagree (each line above says how to draw it again)");
#else
  throw std::invalid_argument("this build has no rtl engine to check against the model (--list still lists the cases)");
#endif
}

}  // namespace

void register_crosscheck(CLI::App& app) {
  auto args = std::make_shared<CrosscheckArgs>();
  auto* cmd = app.add_subcommand(
      "crosscheck",
      "Draw random renders on the model and on the RTL (or the simulated SoC) and compare them pixel for pixel");
  cmd->add_option("--seed", args->seed, "the sequence of cases (the same on every machine)")->capture_default_str();
  cmd->add_option("--first", args->first, "the first case's number in the sequence")->capture_default_str();
  cmd->add_option("--count", args->count, "how many cases")
      ->check(CLI::Range(uint32_t{1}, uint32_t{10000000}))
      ->capture_default_str();
  cmd->add_option("--minutes", args->minutes, "stop starting cases after this long (0: no limit)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--out-dir", args->out_dir, "write both engines' frames of every case that differs here");
  cmd->add_flag("--list", args->list, "print the cases without drawing them");
  cmd->add_option("--engine", args->engine,
                  "what draws beside the model: rtl (the Verilated GPU), or soc (the console firmware on the "
                  "simulated SoC, against the model drawing the console's own triangles)")
      ->check(CLI::IsMember({"rtl", "soc"}))
      ->capture_default_str();
  cmd->add_option("--max-triangles", args->max_triangles,
                  "skip a case whose scene has more triangles (default: " + std::to_string(kSocMaxTriangles) +
                      " on soc, no limit on rtl)")
      ->check(CLI::Range(uint32_t{1}, UINT32_MAX));
  cmd->callback([args] { run_crosscheck(*args); });
}

}  // namespace htx
