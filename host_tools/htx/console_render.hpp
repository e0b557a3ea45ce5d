// A scene drawn by the console firmware (docs/console.md) and brought back: the `soc` and `board`
// engines of htx render (docs/engines.md). The scene is uploaded in its packed form with its
// textures, the console is set up, draws it (`render upload`) and sends the frame (`grab`). A
// scene larger than the console's store goes in parts, each uploaded and drawn over the last
// (`render upload over`), the frame shown once the last is drawn.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "console_payload.hpp"
#include "htx/console/console_client.hpp"

namespace htx {

struct ConsoleDraw {
  ScenePayload payload;   // the scene as htx upload sends it (console_payload.hpp)
  std::string method;     // `set method`'s name: auto, affine, subdivN, recip_lut, recip_nr, divfree
  uint32_t tolerance_denominator = 64;  // `set tolerance 1/N`'s N
  std::string filter;     // `set filter`'s name; `scene` keeps the meshes' own
  // Told each step as it begins ("upload: scene of 816 bytes", ..., "grab: the frame"), and what
  // the payload's packing did to the scene or its texture (its note), for progress.
  std::function<void(const std::string&)> on_step;
};

struct ConsoleDrawn {
  console::GrabbedFrame frame;
  // The render line's figures: triangles, sent, frame_cycles, raster_cycles, fragments (summed
  // over the parts; `-` on a GPU without counters) and crc32 (the whole frame's, after the last).
  std::map<std::string, std::string> figures;
  size_t parts = 0;
};

// Uploads, sets, renders and grabs on a console at its prompt (ConsoleClient::sync done). Throws
// std::runtime_error with the console's own error line when it refuses a step, and when the
// frame's checksum is not the one its render printed.
ConsoleDrawn draw_on_console(console::ConsoleClient& client, const ConsoleDraw& draw);

}  // namespace htx
