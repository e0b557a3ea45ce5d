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

// Where a chain of `need` blocks goes: at the start of the lowest gap find_texture_gap finds, or,
// when that gap runs to the memory's end, at the end. A texture replaced beside its old chain then
// leaves the freed blocks joined to the free space instead of splitting it in two (the lowest gap
// alone put a 32 x 32 replacement of the boot texture in the middle of 1,024 blocks, after which
// a 64 x 16 chain of 344 blocks found no room with 682 free). `total` when nothing fits.
uint32_t place_texture_chain(const TextureRegion* live, uint32_t count, uint32_t need, uint32_t total);

}  // namespace htx::render
