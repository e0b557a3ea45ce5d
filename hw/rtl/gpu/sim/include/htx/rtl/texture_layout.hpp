// Where a texture's mip chain lives in the texture memory window and how its descriptor reads
// (docs/texture.md, "Memory layout" and "Registers"): the layout the texture unit samples from.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "htx/model/types.hpp"

namespace htx::rtl {

// Blocks (2x2 texels) the whole chain of tex takes.
uint32_t texture_chain_blocks(const Texture& tex);

// Appends (bus address, word) for every texel of every level of tex, the chain starting at block
// base_block of the window at window_base.
void append_texture_words(const Texture& tex, uint32_t base_block, uint32_t window_base,
                          std::vector<std::pair<uint32_t, uint32_t>>& out);

// TEXTURE.TEXn value for tex stored at base_block (BASE, LOG2_WIDTH, LOG2_HEIGHT, FORMAT).
uint32_t texture_descriptor(const Texture& tex, uint32_t base_block);

}  // namespace htx::rtl
