// htx render: render a built-in scene or an OBJ file on the `ref`, `model` or (when built) `rtl`
// engine, write a PNG, and optionally the metrics of the frame against `ref` as JSON. `soc` and
// `board` draw it on the console firmware (render_on_console.cpp).
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "frame_size.hpp"
#include "htx/fw/auto_scene.h"
#include "htx/model/geometry.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/model.hpp"
#include "htx/model/names.hpp"
#include "htx/model/ref.hpp"
#include "htx/model/scenes.hpp"
#include "htx/render/tri_state.h"
#if __has_include("htx/rtl/raster_engine.hpp")
#include "htx/rtl/raster_engine.hpp"
#define HTX_HAVE_RTL_ENGINE 1
#endif
#include "metrics_output.hpp"
#include "output_path.hpp"
#include "render_args.hpp"
#include "render_setup.hpp"

namespace htx {

namespace {

// What AUTO gave the triangles that asked for it (docs/auto.md): a line for the user and the
// metrics' "auto" object, by the raster unit's method names.
std::string auto_summary_line(const fw::AutoSceneSummary& s, double tolerance) {
  char tol[32];
  std::snprintf(tol, sizeof tol, "%g", tolerance);
  std::string line = "auto: " + std::to_string(s.resolved) + " triangles at " + tol + " texel:";
  const char* sep = " ";
  for (uint32_t m = 0; m < render::kMethodNameCount; ++m) {
    if (s.per_method[m] == 0) continue;
    line += sep + std::string(render::kMethodNames[m]) + " " + std::to_string(s.per_method[m]);
    sep = ", ";
  }
  return line + "; " + std::to_string(s.skipped) + " without comparing (choosing would not pay), " +
         std::to_string(s.not_within) + " with no method predicted within the tolerance";
}

nlohmann::json auto_summary_json(const fw::AutoSceneSummary& s) {
  nlohmann::json methods = nlohmann::json::object();
  for (uint32_t m = 0; m < render::kMethodNameCount; ++m)
    if (s.per_method[m] > 0) methods[render::kMethodNames[m]] = s.per_method[m];
  return {{"triangles", s.resolved}, {"methods", methods}, {"skipped", s.skipped}, {"not_within", s.not_within}};
}

#ifdef HTX_HAVE_RTL_ENGINE
constexpr const char* kEngines = "ref, model, rtl, soc or board";
#else
constexpr const char* kEngines = "ref, model, soc or board";
#endif

}  // namespace

void require_render_outputs(const RenderArgs& a, const Scene& scene) {
  for (const std::string* out : {&a.out, &a.metrics}) {
    for (const std::string& source : scene.sources) require_not_input(*out, source);
    if (!a.firmware.empty()) require_not_input(*out, a.firmware);
  }
}

namespace {

void run_render(const RenderArgs& given) {
  require_given_path(given.out, "--out");
  require_output_files({&given.out, &given.metrics});
  // --tolerance bounds AUTO's choice; with another method for every triangle it would do nothing.
  if (given.tolerance_given && !given.method.empty() && parse_method(given.method).method != Method::Auto)
    throw std::invalid_argument("--tolerance is AUTO's (--method auto, or a scene's own AUTO triangles); --method " +
                                given.method + " draws every triangle without it");
  if (given.engine == "soc" || given.engine == "board") return render_on_console(given);
#ifdef HTX_HAVE_RTL_ENGINE
  const bool known = given.engine == "ref" || given.engine == "model" || given.engine == "rtl";
#else
  const bool known = given.engine == "ref" || given.engine == "model";
#endif
  if (!known) throw std::invalid_argument("--engine '" + given.engine + "': this build renders on " + kEngines);
  // The console engines' options, refused here rather than ignored.
  if (!given.firmware.empty()) throw std::invalid_argument("--firmware is for --engine soc");
  if (!given.port.empty()) throw std::invalid_argument("--port is for --engine board");
  if (given.baud_given) throw std::invalid_argument("--baud is for --engine board");
  if (given.fast_baud != 0) throw std::invalid_argument("--fast-baud is for --engine board");
  if (given.timeout_given) throw std::invalid_argument("--timeout is for --engine soc and board");
  // ref draws every triangle exactly (float64 perspective): a method would be ignored without a word.
  if (given.engine == "ref" && !given.method.empty())
    throw std::invalid_argument(
        "--method: ref draws every triangle exactly; the methods are the model's, rtl's, "
        "soc's and board's (ref is what --metrics compares them with)");
  RenderArgs a = given;
  if (a.size.empty()) a.size = "320x240";
  if (a.config.empty()) a.config = "full";
  int width = 0, height = 0;
  parse_size(a.size, width, height);
  const Scene scene = load_scene(a.scene);
  require_render_outputs(a, scene);
  for (const std::string& note : scene.notes) std::cerr << "htx: " << note << "\n";
  ScreenScene screen = prepare_screen_scene(scene, width, height);
  override_triangle_states(screen, a.method, a.filter, a.untextured);
#ifdef HTX_HAVE_RTL_ENGINE
  // The RTL builds the named configurations but for the model's QUADRATIC (rtl_config).
  const ModelConfig config = a.engine == "rtl" ? named_config(a.config, rtl_config) : named_config(a.config);
  RtlStats rtl_stats;
#else
  const ModelConfig config = named_config(a.config);
#endif
  // AUTO: the firmware's per-triangle choice (docs/auto.md) within --tolerance texels.
  const fw::AutoSceneSummary auto_summary = fw::resolve_auto_methods(screen, config, static_cast<float>(a.tolerance));
  if (auto_summary.resolved > 0) std::cout << auto_summary_line(auto_summary, a.tolerance) << "\n";
  RefOptions ref_options;
  ref_options.depth_bits = config.z_bits;

  // A method the scene's own triangles ask for (no --method given) that this configuration lacks:
  // refused here, saying where it came from and what would draw them (the engines' own refusal,
  // the same test, names only the method). ref draws every triangle exactly and takes any.
  if (a.method.empty() && a.engine != "ref")
    for (const ScreenTri& t : screen.tris)
      if (t.state.method != Method::Auto && !config.has_method(t.state.method))
        throw std::invalid_argument("method " + method_name(t.state.method, t.state.subdiv_n) +
                                    " is not built in configuration " + config.name +
                                    " (the scene's triangles ask for it; --method auto picks a built one)");

  const auto t0 = std::chrono::steady_clock::now();
#ifdef HTX_HAVE_RTL_ENGINE
  const Frame frame = a.engine == "ref"     ? render_ref(screen, ref_options)
                      : a.engine == "model" ? render_model(screen, config)
                                            : render_rtl(screen, config, &rtl_stats);
#else
  const Frame frame = a.engine == "ref" ? render_ref(screen, ref_options) : render_model(screen, config);
#endif
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  write_png(a.out, image_from_rgb565(frame.width, frame.height, frame.color));
  // Triangles the vertex-record encoder refused, which the firmware would not send either (ref
  // draws every one): said as the soc engine says the console's.
  const uint64_t dropped = frame.counters.dropped;
  std::cout << a.engine << " rendered " << a.scene << " (" << screen.tris.size() << " triangles, "
            << (dropped > 0 ? std::to_string(dropped) + " dropped, " : "") << width << "x" << height << ") in " << ms
            << " ms -> " << a.out << "\n";
  if (dropped > 0)
    std::cerr << "htx render: " << a.engine << " dropped " << dropped
              << " triangles: the vertex-record format cannot hold them (texture coordinates out of its range)\n";

  if (!a.metrics.empty()) {
    const Frame ref = a.engine == "ref" ? frame : render_ref(screen, ref_options);
    MetricsLabels labels{a.engine, a.scene, a.method.empty() ? "scene" : a.method,
                         a.filter.empty() ? "scene" : a.filter, a.engine == "ref" ? "-" : a.config};
    nlohmann::json j = metrics_to_json(compute_metrics(frame, ref, labels));
    if (a.engine == "model") j["cycles"] = frame.counters.cycles;  // the model's estimate (docs/model.md §9)
    if (a.engine != "ref") j["dropped"] = dropped;
    if (auto_summary.resolved > 0) j["auto"] = auto_summary_json(auto_summary);
#ifdef HTX_HAVE_RTL_ENGINE
    if (a.engine == "rtl") {
      j["cycles"] = rtl_stats.cycles;
      j["covered_pixels"] = rtl_stats.covered_pixels;
      j["px_per_clk"] = rtl_stats.px_per_clk;
      j["triangles"] = rtl_stats.triangles;
      j["setup_cycles_per_triangle"] = rtl_stats.setup_cycles_per_triangle;
      const Frame model = render_model(screen, config);
      const uint64_t mismatch = frame_mismatch_pixels(frame, model);
      j["model_mismatch_pixels"] = mismatch;
      // CNT_DIVFREE_STEPS and the model's divfree_steps_total on the same records.
      j["divfree_steps_total"] = rtl_stats.divfree_steps;
      j["model_divfree_steps_total"] = model.counters.divfree_steps_total;
      // The Verilated GPU has no per-pixel probe (docs/metrics.md). Where its frame is the model's
      // on the same records, colour and depth at every pixel, the model's probe is the frame's (the
      // coordinates themselves are checked bit for bit by the rtl tests); otherwise none is given.
      if (mismatch == 0)
        take_probe_figures(metrics_to_json(compute_metrics(model, ref, labels)), &j);
      else
        null_probe_figures(&j);
    }
#endif
    write_metrics(a.metrics, j);
  }
}

}  // namespace

void register_render(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Render a scene (built-in NAME[:k=v,...] or FILE.obj) to a PNG");
  cmd->add_option("scene", args->scene, "built-in scene spec (see `htx scenes`) or an OBJ file")->required();
  cmd->add_option("--engine", args->engine,
                  "ref | model | rtl (when built) | soc (the console firmware on the simulated SoC) | board "
                  "(the console firmware on a board, --port)")
      ->capture_default_str();
  cmd->add_flag("--untextured", args->untextured, "draw every triangle untextured (its colour only)");
  cmd->add_option("--method", args->method,
                  "override every triangle's perspective method: affine, subdivN (2..64), recip_lut, recip_nr, "
                  "divfree, quadratic, auto");
  cmd->add_option("--tolerance", args->tolerance, "AUTO: largest predicted texel-coordinate error (texels)")
      ->check(positive_finite())
      ->capture_default_str();
  cmd->add_option("--filter", args->filter, "override every triangle's filter: nearest, bilinear, trilinear");
  cmd->add_option("--config", args->config,
                  "model configuration: full | icebreaker | icebreaker-board (icebreaker with the board GPU's "
                  "methods only: affine, recip_lut); default full, on soc and board icebreaker (the SoC's GPU)")
      ->check(CLI::IsMember({"full", "icebreaker", "icebreaker-board"}));
  cmd->add_option("--size", args->size,
                  "frame size WxH; default 320x240, on soc and board 160x120 (the console's screen)");
  cmd->add_option("--out", args->out, "output PNG")->required();
  cmd->add_option("--metrics", args->metrics, "also render ref and write the metrics JSON here");
  cmd->add_option("--firmware", args->firmware, "soc: the console firmware's ELF (default: the build's console.elf)");
  cmd->add_option("--port", args->port, "board: its serial port (or the pty of `htx sim --uart pty`)");
  cmd->add_option("--baud", args->baud, "board: baud rate (a pty ignores it)")->capture_default_str();
  cmd->add_option("--fast-baud", args->fast_baud,
                  "board: switch the console and the port to this rate for the transfers (the console's `baud`) "
                  "and back to --baud at the end, also after an error")
      ->check(CLI::Range(uint32_t{1}, uint32_t{3000000}));  // (0 is how the code says "not given")
  cmd->add_option("--timeout", args->timeout_s, "soc and board: longest silence to wait through, seconds")
      ->check(timeout_seconds())
      ->capture_default_str();
  cmd->callback([args, cmd] {
    args->baud_given = cmd->count("--baud") > 0;
    args->timeout_given = cmd->count("--timeout") > 0;
    args->tolerance_given = cmd->count("--tolerance") > 0;
    run_render(*args);
  });
}

}  // namespace htx
