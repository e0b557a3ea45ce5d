// The model's frame of what the console draws from a payload: the console's own plan
// (render_app::plan_draw) and the firmware pipeline, run on the host into the model, whose frame
// carries the per-pixel probe the console has not got. Where it is, pixel for pixel, the frame the
// console sent, its probe is that frame's, and the soc and board engines report texel errors with
// it (docs/metrics.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "console_render.hpp"
#include "htx/console/console_client.hpp"
#include "htx/model/types.hpp"

namespace htx {

// What the model needs of the console beyond the payload, from its `info` (asked after a draw):
// bit i of methods_built is STATE method i, of filters_built filter i (htx/render/tri_state.h's
// names), and whether slot 0 holds an uploaded texture (`texture 0: ... (uploaded)`): the
// payload's, or, when it sent none for slot 0, one from an earlier session.
struct ConsoleCaps {
  uint32_t methods_built = 0, filters_built = 0;
  bool slot0_uploaded = false;
};
ConsoleCaps console_caps(console::ConsoleClient& client);

struct ConsoleModel {
  Frame frame;                  // the model's, with its probe
  std::vector<Texture> slots;   // the texture each slot of the console draws with (a slot the
                                // payload leaves empty: slot 0's, as the console's plan falls back)
  uint64_t triangles = 0, sent = 0;  // the pipeline's counts over the parts (the console prints them)
};

// `draw`'s payload in its parts, with its method, tolerance and filter as the console takes them,
// for the console `caps` describes. Slot 0 holds the console's boot checkerboard unless the
// payload sends one or caps says an earlier upload is there, whose texels htx has not got. Throws
// std::runtime_error when the console would refuse the draw or the model cannot draw it (a
// triangle that samples such a slot 0 among them).
ConsoleModel console_model_frame(const ConsoleDraw& draw, const ConsoleCaps& caps);

// Why the model's frame is not the one the console sent (empty when it is: every pixel, and the
// triangle counts, since the same pixels from other triangles would be a coincidence to catch).
std::string console_model_disagreement(const ConsoleModel& model, const ConsoleDrawn& drawn);

}  // namespace htx
