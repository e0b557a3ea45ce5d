// The render state the firmware draws the built-in scenes with. The SoC's GPU has no texture unit
// yet (docs/soc.md, "GPU"), so meshes are drawn untextured with Gouraud colour; AUTO picks each
// triangle's method. The system test applies the same state on its cosim reference.
#pragma once

#include "htx/render/pipeline.h"

namespace render_app {

inline void apply_soc_render_state(htx::render::Mesh* mesh) {
  mesh->state.textured = false;
  mesh->state.gouraud = true;
  mesh->state.method = htx::render::kMethodAuto;
}

}  // namespace render_app
