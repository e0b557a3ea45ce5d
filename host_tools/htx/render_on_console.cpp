#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "cli_checks.hpp"
#include "console_model.hpp"
#include "console_payload.hpp"
#include "console_render.hpp"
#include "console_scene.hpp"
#include "htx/console/console_client.hpp"
#include "htx/console/serial_port.hpp"
#include "htx/model/geometry.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/model.hpp"
#include "htx/model/names.hpp"
#include "htx/model/ref.hpp"
#include "htx/model/scenes.hpp"
#include "htx_paths.h"
#include "metrics_output.hpp"
#include "render_args.hpp"
#include "soc_config.hpp"
#if __has_include("htx/sim/soc_sim.hpp")
#include "soc_console.hpp"
#define HTX_HAVE_SOC_CONSOLE 1
#endif

namespace htx {

namespace {

// The console's screen and clear colour: its render firmware's (firmware/app/render).
constexpr int kScreenWidth = render_app::kWidth, kScreenHeight = render_app::kHeight;
constexpr const char* kSocConfig = "icebreaker";  // the simulated SoC's and the ULX3S's GPU
constexpr unsigned kSocBaud = 1'000'000;          // soc: the console's `baud` once it is up

// A number as printf's %g writes it (std::to_string's fixed six decimals write 1e-7 as 0.000000).
std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// `set tolerance 1/N`'s N for `t` texels, when it is one (N = 1..65536).
uint32_t tolerance_denominator(double t) {
  const double n = std::round(1.0 / t);
  if (!(t > 0) || n < 1 || n > 65536 || std::fabs(1.0 / n - t) > 1e-9 * t)
    throw std::invalid_argument("--tolerance " + shortest(t) +
                                ": the console takes 1/N texel (N = 1..65536), e.g. 0.015625 for 1/64");
  return static_cast<uint32_t>(n);
}

// The console draws every triangle with one method (`set method`): --method, else the scene's
// own when all its triangles have the same one.
std::string console_method(const RenderArgs& a, const ScreenScene& screen) {
  if (!a.method.empty()) {
    const MethodChoice m = parse_method(a.method);
    if (m.method == Method::Quadratic) throw std::invalid_argument("--method quadratic: only the model builds it");
    return method_name(m.method, m.subdiv_n);
  }
  std::optional<std::string> name;
  for (const ScreenTri& t : screen.tris) {
    const std::string n = method_name(t.state.method, t.state.subdiv_n);
    if (name && *name != n)
      throw std::invalid_argument(
          "the scene's triangles use more than one method, and the console draws every "
          "triangle with one: give --method");
    name = n;
  }
  return name.value_or("auto");
}

// The console's `baud`, with the port following, announced as a step.
void switch_line(console::ConsoleClient& client, const ConsoleDraw& draw, unsigned baud, const char* how = "to") {
  draw.on_step(std::string("serial line ") + how + " " + std::to_string(baud) + " baud");
  client.set_baud(baud);
}

std::string console_firmware(const RenderArgs& a) {
  const std::string elf = a.firmware.empty() ? std::string(HTX_PATH_FIRMWARE_DIR) + "/console.elf" : a.firmware;
  if (!std::filesystem::is_regular_file(elf))
    throw std::invalid_argument("no console firmware at '" + elf +
                                "' (build the `firmware` target, or give --firmware FILE)");
  return elf;
}

// The texel errors of the frame a console sent (docs/engines.md, "`soc` and `board`"): the console
// has no per-pixel probe; the model drawing the console's own triangles has one, and where its
// frame is the one the console sent, pixel for pixel, with the same counts, it is that frame's.
// Otherwise the probe's figures are null and stderr says why.
void console_probe_figures(const Scene& scene, const ConsoleDraw& draw, const ConsoleDrawn& drawn,
                           const ConsoleCaps& caps, bool untextured, const RefOptions& ref_options,
                           const MetricsLabels& labels, const std::string& engine, nlohmann::json* j) {
  const auto no_probe = [j, &engine](const std::string& why) {
    null_probe_figures(j);
    std::cerr << engine << ": metrics: no texel errors: " << why << std::endl;
  };
  try {
    const ConsoleModel model = console_model_frame(draw, caps);
    const std::string disagreement = console_model_disagreement(model, drawn);
    if (!disagreement.empty()) return no_probe(disagreement);
    // Texel errors are in texels of the texture sampled, and the console's are the scene's brought
    // to its size limit, so they are taken against ref drawing with those (the texture's size
    // scales the texel coordinates as the screen scene is prepared).
    Scene same_textures = scene;
    for (size_t i = 0; i < same_textures.textures.size(); ++i) {
      const size_t slot = i < draw.payload.slot_of_texture.size() ? draw.payload.slot_of_texture[i] : 0;
      same_textures.textures[i] = model.slots.at(slot);
    }
    const Frame ref_same = render_ref(console_screen(same_textures, untextured), ref_options);
    take_probe_figures(metrics_to_json(compute_metrics(model.frame, ref_same, labels)), j);
  } catch (const std::exception& e) {
    no_probe(std::string("the model cannot draw the console's triangles: ") + e.what());
  }
}

// "WxH" of the console's screen.
std::string console_screen_size() {
  return std::to_string(kScreenWidth) + "x" + std::to_string(kScreenHeight);
}

}  // namespace

ScreenScene console_screen(const Scene& scene, bool untextured) {
  ScreenScene s = prepare_screen_scene(scene, kScreenWidth, kScreenHeight);
  s.clear_color = render_app::kClearColor;
  if (untextured)
    for (ScreenTri& t : s.tris) t.state.textured = false;
  return s;
}

ConsoleScene prepare_console_scene(const RenderArgs& a) {
  const bool soc = a.engine == "soc";
  const std::string screen_size = console_screen_size();
  if (!a.size.empty() && a.size != screen_size)
    throw std::invalid_argument("--size " + a.size + ": --engine " + a.engine + " draws the console's " + screen_size +
                                " screen only");
  if (!a.config.empty() && a.config != kSocConfig)
    throw std::invalid_argument("--config " + a.config + ": --engine " + a.engine + " draws on the SoC's GPU, " +
                                kSocConfig);
  if (soc && !a.port.empty()) throw std::invalid_argument("--port is for --engine board (soc runs its own SoC)");
  if (!soc && a.port.empty()) throw std::invalid_argument("--engine board needs --port (the board's serial port)");
  if (!soc && !a.firmware.empty()) throw std::invalid_argument("--firmware is for --engine soc");
  if (soc && a.fast_baud != 0)
    throw std::invalid_argument("--fast-baud is for --engine board (soc switches its own line to " +
                                std::to_string(kSocBaud) + " baud)");
  if (a.fast_baud != 0) {
    try {
      console::SerialPort::check_baud(a.fast_baud);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--fast-") + e.what());  // "--fast-baud N: want ..."
    }
  }
  if (soc && a.baud_given)
    throw std::invalid_argument("--baud is for --engine board (soc's line has no rate: it runs at " +
                                std::to_string(kSocBaud) + " baud once the console is up)");

  ConsoleScene c;
  // (The scene's notes come with the upload's, as a step.)
  c.scene = load_scene(a.scene);
  c.screen = console_screen(c.scene, a.untextured);
  c.draw.payload = scene_payload(c.scene, a.scene, screen_size, true, render::kMaxPackedMeshVertices, a.untextured);
  c.draw.method = console_method(a, c.screen);
  c.draw.tolerance_denominator = tolerance_denominator(a.tolerance);
  c.draw.filter = a.filter.empty() ? "scene" : std::string(filter_name(parse_filter(a.filter)));
  return c;
}

ConsoleRun draw_console_scene(const RenderArgs& a, ConsoleDraw draw, bool want_caps,
                              const std::function<void(const std::string&)>& on_step) {
  draw.on_step = on_step ? on_step : [](const std::string&) {};
  const auto t0 = std::chrono::steady_clock::now();
  const auto timeout = timeout_ms(a.timeout_s);
  ConsoleRun run;
  if (a.engine == "soc") {
#ifdef HTX_HAVE_SOC_CONSOLE
    draw.on_step("starting the console firmware on the simulated SoC");
    SocConsole sim(console_firmware(a));
    std::optional<console::SerialPort> port;  // open until the run ends after `quit`
    try {
      port.emplace(sim.pty(), 115200);  // (a pseudo-terminal has no rate; --baud is the board's)
      console::ConsoleClient client(*port, timeout);
      client.sync();
      // The simulated line has no cable to limit it: 1 Mbaud (12 clocks a bit) takes the transfers,
      // most of the run at 115,200 baud, down by a factor of nine.
      switch_line(client, draw, kSocBaud);
      run.drawn = draw_on_console(client, draw);
      if (want_caps) run.caps = console_caps(client);
      port->write("quit\r");
    } catch (const std::runtime_error& e) {
      // A console that went quiet because the SoC's run had ended (its pseudo-terminal closes then)
      // says how it ended.
      if (const std::optional<std::string> how = sim.ended_early())
        throw std::runtime_error(std::string(e.what()) + "; " + *how);
      throw;
    }
    const sim::SimResult r = sim.finish(timeout);
    run.where = "the simulated SoC, " + std::to_string(r.cycles) + " clocks";
#else
    throw std::invalid_argument("--engine soc: this build has no SoC simulation");
#endif
  } else {
    console::SerialPort port(a.port, a.baud);
    console::ConsoleClient client(port, timeout);
    client.sync();
    if (a.fast_baud == 0) {
      run.drawn = draw_on_console(client, draw);
    } else {
      // The board is left at --baud, where the next `htx console` expects it, whatever happened
      // (a switch the console refused leaves it there already, and switching back is harmless).
      const auto back = [&] { switch_line(client, draw, a.baud, "back to"); };
      try {
        switch_line(client, draw, a.fast_baud);
        run.drawn = draw_on_console(client, draw);
      } catch (...) {
        try {
          back();
        } catch (const std::exception& again) {
          std::cerr << "board: could not switch the line back to " << a.baud << " baud: " << again.what() << "\n";
        }
        throw;
      }
      back();
    }
    if (want_caps) run.caps = console_caps(client);
    run.where = a.port;
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const console::GrabbedFrame& g = run.drawn.frame;
  if (g.width != kScreenWidth || g.height != kScreenHeight)
    throw std::runtime_error("the console sent a " + std::to_string(g.width) + "x" + std::to_string(g.height) +
                             " frame, not " + console_screen_size());
  return run;
}

void render_on_console(const RenderArgs& a) {
  const ConsoleScene c = prepare_console_scene(a);
  require_render_outputs(a, c.scene);
  const ConsoleRun run = draw_console_scene(a, c.draw, !a.metrics.empty(), [&a](const std::string& what) {
    std::cerr << a.engine << ": " << what << std::endl;
  });
  const ConsoleDrawn& drawn = run.drawn;
  const console::GrabbedFrame& g = drawn.frame;
  write_png(a.out, image_from_rgb565(g.width, g.height, g.pixels));
  std::cout << a.engine << " rendered " << a.scene << " (" << drawn.figures.at("triangles") << " triangles, "
            << drawn.figures.at("sent") << " sent, " << g.width << "x" << g.height << ", method " << c.draw.method
            << ") on " << run.where << " in " << run.seconds << " s, crc32 " << drawn.figures.at("crc32") << " -> "
            << a.out << "\n";
  if (drawn.figures.count("dropped") && drawn.figures.at("dropped") != "0")
    std::cerr << "htx render: the console dropped " << drawn.figures.at("dropped")
              << " triangles: the vertex-record format cannot hold them (texture coordinates out of its "
                 "range), or clipping left a triangle a few ulps across with more corners than it holds\n";

  if (!a.metrics.empty()) {
    RefOptions ref_options;
    ref_options.depth_bits = model_config(kSocConfig).z_bits;
    const Frame ref = render_ref(c.screen, ref_options);
    Frame frame;
    frame.width = g.width;
    frame.height = g.height;
    frame.color = g.pixels;
    frame.probe.assign(g.pixels.size(), PixelProbe{});  // the console has no per-pixel probe (below)
    const MetricsLabels labels{a.engine, a.scene, c.draw.method, c.draw.filter, kSocConfig};
    nlohmann::json j = metrics_to_json(compute_metrics(frame, ref, labels));
    // The figures the console printed: the raster unit's busy clocks (CNT_BUSY; null on a GPU
    // without counters), the CPU's clocks for the frame, the triangles it drew and sent.
    const auto number_or_null = [](const std::string& v) -> nlohmann::json {
      if (v == "-") return nullptr;
      return std::stoull(v);
    };
    j["cycles"] = number_or_null(drawn.figures.at("raster_cycles"));
    j["cpu_frame_cycles"] = number_or_null(drawn.figures.at("frame_cycles"));
    j["triangles"] = number_or_null(drawn.figures.at("triangles"));
    j["sent"] = number_or_null(drawn.figures.at("sent"));
    if (drawn.figures.count("dropped")) j["dropped"] = number_or_null(drawn.figures.at("dropped"));
    j["crc32"] = drawn.figures.at("crc32");
    // AUTO's skipped choices, which a console from before 2026-12-06 does not print.
    if (c.draw.method == "auto" && drawn.figures.count("auto_skipped"))
      j["auto"] = {{"skipped", number_or_null(drawn.figures.at("auto_skipped"))}};
    console_probe_figures(c.scene, c.draw, drawn, run.caps, a.untextured, ref_options, labels, a.engine, &j);
    write_metrics(a.metrics, j);
  }
}

}  // namespace htx
