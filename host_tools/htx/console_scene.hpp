// A scene drawn on the console firmware for `htx render --engine soc|board`, in its two steps:
// prepared on the host (checked, packed, its method, tolerance and filter as the console takes
// them), then drawn on the console and brought back. `htx crosscheck --engine soc` takes them one by
// one to set the console's frame beside the model's.
#pragma once

#include <functional>
#include <string>

#include "console_model.hpp"
#include "console_render.hpp"
#include "htx/model/scenes.hpp"
#include "htx/model/types.hpp"
#include "render_args.hpp"

namespace htx {

struct ConsoleScene {
  Scene scene;
  ScreenScene screen;  // as the console's screen shows it (its size and background), for ref
  ConsoleDraw draw;    // without on_step
};

struct ConsoleRun {
  ConsoleDrawn drawn;
  ConsoleCaps caps;   // asked only when wanted (for the model of the console's triangles)
  std::string where;  // "the simulated SoC, N clocks" or the port
  double seconds = 0;
};

// The scene on the console's screen, --untextured applied.
ScreenScene console_screen(const Scene& scene, bool untextured);

// Checks the options the console engines take and prepares `a.scene`. Throws
// std::invalid_argument for what the console cannot draw as asked (a size or configuration not its
// own, QUADRATIC, a tolerance that is not 1/N, a scene whose triangles ask for several methods).
ConsoleScene prepare_console_scene(const RenderArgs& a);

// Draws it on a fresh simulated SoC (`soc`) or on a board at a.port, each step told to `on_step`
// (may be empty). Throws std::runtime_error with the console's own line when it refuses a step, and
// when the console or the SoC's run fails.
ConsoleRun draw_console_scene(const RenderArgs& a, ConsoleDraw draw, bool want_caps,
                              const std::function<void(const std::string&)>& on_step);

}  // namespace htx
