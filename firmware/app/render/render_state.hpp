// The render state the firmware draws the built-in scenes with: textured with the firmware's
// checkerboard (soc_texture.hpp, slot 0, 32 x 32), modulated by Gouraud colour, with the scene's
// filter, wraps and depth state; AUTO picks each triangle's method. The system test applies the
// same state on its cosim reference.
#pragma once

#include "htx/render/pipeline.h"
#include "soc_texture.hpp"

namespace render_app {

inline void apply_soc_render_state(htx::render::Mesh* mesh) {
  mesh->state.textured = true;
  mesh->state.texture = static_cast<uint8_t>(kTextureSlot);
  mesh->tex = {kTextureLog2, kTextureLog2};
  mesh->state.gouraud = true;
  mesh->state.method = htx::render::kMethodAuto;
}

}  // namespace render_app
