// Mip-chain generation (docs/model.md §7): level l+1 is the 2x2 box of level l's decoded texels,
// (a+b+c+d+2) >> 2 per channel ((a+b+1) >> 1 once one side is 1 texel), then encoded; level 0 is the
// encoded image. Bit-exact with the model's make_texture (hw/model texture.cpp), so frames drawn
// from an uploaded chain equal the model's. No heap: the caller owns every buffer. Freestanding C++17.
#pragma once

#include <stdint.h>

namespace htx::fw {

inline constexpr unsigned kTexMinLog2 = 3;  // 8 texels
inline constexpr unsigned kTexMaxLog2 = 8;  // 256 texels

// Levels of a complete chain of a 2^log2_w x 2^log2_h texture: down to 1x1.
inline unsigned mip_level_count(unsigned log2_w, unsigned log2_h) { return (log2_w > log2_h ? log2_w : log2_h) + 1; }
// log2 of a level's side: max(0, log2_side - level).
inline unsigned mip_level_log2(unsigned log2_side, unsigned level) { return level >= log2_side ? 0 : log2_side - level; }

// Where the level above comes from.
enum MipSource : uint8_t {
  kMipSourceRgba8 = 0,   // the 8-bit RGBA image of level 0 (each pixel encoded, then decoded, as level 0 stores it)
  kMipSourceTexels = 1,  // texels of the format (a level already generated)
};

// Writes the level below src (2^log2_w x 2^log2_h, row-major) into dst as texels of `format`:
// max(1, w/2) x max(1, h/2) of them. dst may be src itself when src holds texels (every texel is
// written after the last read of the texels below its index). An unknown format writes nothing.
void mip_next_level(uint8_t format, const uint32_t* src, MipSource source, unsigned log2_w, unsigned log2_h,
                    uint32_t* dst);

}  // namespace htx::fw
