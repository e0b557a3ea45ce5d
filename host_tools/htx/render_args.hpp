// htx render's options, shared by its engines on the host (cmd_render.cpp) and on the console
// firmware (render_on_console.cpp).
#pragma once

#include <string>

namespace htx {

struct RenderArgs {
  std::string scene;
  std::string engine = "ref";
  std::string method;
  std::string filter;
  std::string config;  // empty: full on the host engines, icebreaker (the SoC's GPU) on soc and board
  std::string size;    // empty: 320x240 on the host engines, 160x120 (the console's screen) on soc and board
  std::string out;
  std::string metrics;
  double tolerance = 1.0 / 64;
  bool untextured = false;
  // soc and board
  std::string firmware;  // soc: the console firmware's ELF (empty: the build's)
  std::string port;      // board: its serial port
  unsigned baud = 115200;
  unsigned fast_baud = 0;  // board: the rate for the transfers (0: stay at baud)
  double timeout_s = 120;
  bool baud_given = false;     // --baud given (board only; soc and the host engines refuse it)
  bool timeout_given = false;  // --timeout given (the host engines refuse it)
  bool tolerance_given = false;  // --tolerance given (refused with a --method other than auto)
};

struct Scene;

// --out and --metrics checked before the render: a path given and writable, and none of them one
// of the scene's own files (its OBJ, material libraries, textures) or the --firmware ELF.
void require_render_outputs(const RenderArgs& a, const Scene& scene);

// `--engine soc` and `--engine board` (docs/engines.md): the scene uploaded to the console
// firmware on the simulated SoC or on a board, drawn there and downloaded; the PNG and the
// metrics as the host engines write them.
void render_on_console(const RenderArgs& a);

}  // namespace htx
