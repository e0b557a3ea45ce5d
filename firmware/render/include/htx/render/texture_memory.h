// Where a texture's mip chain goes in texture memory when several textures live there at once (the
// console's texture slots, docs/console.md "Texture upload"). Texture memory is counted in the
// texture unit's 2 x 2-texel blocks; a chain occupies one run of them (htx/hal/texture.h).
// Freestanding C++17.
#pragma once

#include <stdint.h>

namespace htx::render {

// A run of blocks; `blocks` 0 is no run (an empty slot).
struct TextureRegion {
  uint32_t base = 0, blocks = 0;
};

// The lowest first block of a run of `need` blocks inside [0, total) that overlaps none of the
// `count` regions in `live` (empty ones ignored), or `total` when there is none (or need is 0).
uint32_t find_texture_gap(const TextureRegion* live, uint32_t count, uint32_t need, uint32_t total);

}  // namespace htx::render
