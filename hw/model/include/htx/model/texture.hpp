// Texel formats, mip-chain generation and wrap addressing of the texture unit (docs/model.md,
// "Texture unit"). Bit-exact: the model and the RTL produce the same texels; the float64 reference
// decodes texels with the same functions.
#pragma once

#include <cstdint>
#include <span>

#include "htx/model/types.hpp"

namespace htx {

// A texel widened to 8 bits per channel.
struct Rgba8 {
  uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba8&) const = default;
};

inline constexpr unsigned kMinTexLog2 = 3;  // 8 texels
inline constexpr unsigned kMaxTexLog2 = 8;  // 256 texels

// 8-bit channels to the packed format: each channel rounded to nearest, c_n = round(c * (2^n-1) / 255).
// RGB565 drops alpha. RGBA8888 packs r in bits 7:0, g 15:8, b 23:16, a 31:24.
uint32_t encode_texel(TexFormat format, Rgba8 c);
// Packed texel to 8-bit channels by bit replication (5 bits abcde -> abcdeabc, 4 bits abcd -> abcdabcd);
// RGB565 decodes with alpha 255.
Rgba8 decode_texel(TexFormat format, uint32_t texel);
// Rounding of an 8-bit channel to n bits (n = 4, 5, 6, 8) as encode_texel does it.
unsigned quantise_channel(unsigned c8, unsigned bits);

// Builds a texture with its full mip chain down to 1x1 from 8-bit RGBA pixels (4 bytes per texel,
// r g b a, row-major, row 0 = texel row 0 = the lowest v). Level 0 is the encoded input; each further
// level is a 2x2 box filter of the decoded 8-bit channels of the level above, (a+b+c+d+2)>>2 per
// channel (2x1 boxes, (a+b+1)>>1, once one side is 1 texel), then encoded. Throws
// std::invalid_argument for sizes outside 8..256 or a pixel count that does not match.
Texture make_texture(TexFormat format, unsigned log2_width, unsigned log2_height,
                     std::span<const uint8_t> rgba8);

unsigned level_count(const Texture& tex);  // levels[] size for a complete chain: max(log2 w, log2 h)+1
unsigned level_log2_width(const Texture& tex, unsigned level);   // max(0, log2_width - level)
unsigned level_log2_height(const Texture& tex, unsigned level);
// Texel (i, j) of a level, already wrapped into range, decoded.
Rgba8 fetch_texel(const Texture& tex, unsigned level, unsigned i, unsigned j);

// Wraps an integer texel index into [0, 2^log2_size): repeat (i mod size), clamp (to [0, size-1]),
// mirror (mirrored repeat, period 2*size: ... 1 0 | 0 1 ... size-1 | size-1 ... 0 | 0 1 ...).
unsigned wrap_index(Wrap wrap, int64_t i, unsigned log2_size);

}  // namespace htx
