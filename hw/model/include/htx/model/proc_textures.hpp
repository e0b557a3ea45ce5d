// Procedural textures built in code (no files): checkerboards and gradients, with full mip chains.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/model/texture.hpp"
#include "htx/model/types.hpp"

namespace htx {

// Level-0 pixels, row-major RGBA8 (4 bytes per texel, row 0 = lowest v); make_texture() packs them
// and builds the mip chain.
std::vector<uint8_t> checkerboard_pixels(unsigned log2_width, unsigned log2_height, unsigned cell_log2,
                                         Rgba8 a, Rgba8 b);
// Red along u, green along v, blue as their sum: every texel differs from its neighbours, so a wrong
// texel choice always shows.
std::vector<uint8_t> gradient_pixels(unsigned log2_width, unsigned log2_height);

Texture checkerboard_texture(TexFormat format, unsigned log2_size, unsigned cell_log2, Rgba8 a, Rgba8 b);
Texture gradient_texture(TexFormat format, unsigned log2_size);

}  // namespace htx
