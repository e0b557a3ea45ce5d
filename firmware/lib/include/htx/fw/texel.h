// Texel formats of the texture unit (docs/model.md §7): 8-bit RGBA to RGB565 / RGBA4444 / RGBA8888
// and back, bit-exact with the model (hw/model texture.cpp) and the RTL decoder. Freestanding C++17.
// RGBA8 values are packed r in bits 7:0, g 15:8, b 23:16, a 31:24.
#pragma once

#include <stdint.h>

namespace htx::fw {

// Numbers of the descriptor's FORMAT field (and of htx::TexFormat).
enum TexelFormat : uint8_t { kTexelRgb565 = 0, kTexelRgba4444 = 1, kTexelRgba8888 = 2 };

inline bool texel_format_valid(uint8_t format) { return format <= kTexelRgba8888; }

// round(c * (2^bits - 1) / 255) for an 8-bit channel, without a divider (exact for all inputs).
inline uint32_t quantise_channel(uint32_t c8, uint32_t bits) {
  const uint32_t x = (c8 & 0xFFu) * ((1u << bits) - 1u) + 128u;
  return (x + (x >> 8)) >> 8;
}

// An n-bit channel (n = 4, 5, 6) widened to 8 bits by bit replication.
inline uint32_t widen_channel(uint32_t v, uint32_t bits) {
  return bits == 4 ? (v << 4) | v : (v << (8 - bits)) | (v >> (2 * bits - 8));
}

// Packs 8-bit RGBA into `format` (RGB565 drops alpha). An unknown format gives 0.
uint32_t encode_texel(uint8_t format, uint32_t rgba8);
// Unpacks a texel to 8-bit RGBA (RGB565 with alpha 255). An unknown format gives 0.
uint32_t decode_texel(uint8_t format, uint32_t texel);

}  // namespace htx::fw
