// The packed texture a host uploads to the console (docs/console.md, "Texture upload"): level 0 of
// a texture in a 16-bit texel format, written by the host (pack_texture) and checked and read in
// place by the firmware (unpack_texture), so both use one definition. Freestanding C++17.
//
//   header   "HTXT", u16 version (1), u8 log2 width, u8 log2 height, u8 format (0 RGB565,
//            1 RGBA4444), 3 bytes zero                                                 12 bytes
//   texels   2^(log2 width + log2 height) u16, row-major (row 0 = v = 0)
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace htx::render {

inline constexpr uint16_t kTexturePackVersion = 1;
inline constexpr size_t kTexturePackHeader = 12;

// The most texels of a texture the console takes: two such chains (352 blocks at most, 128 x 8) fit
// the board's texture memory (1,024 blocks) beside each other, with room for a small third; a
// chain of 2,048 texels takes 683. htx upload sends a scene's texture as its largest mip level
// within it.
inline constexpr uint32_t kConsoleTextureTexels = 1024;
// The texture slots the console keeps (the board's texture unit builds 4, CAPS.SLOTS; the console
// uses as many of these as the unit builds). A mesh names its slot in its state (MeshState::texture).
inline constexpr uint32_t kConsoleTextureSlots = 4;

// The bytes of a packed 2^log2_w x 2^log2_h texture.
inline constexpr size_t packed_texture_size(uint32_t log2_w, uint32_t log2_h) {
  return kTexturePackHeader + (size_t{2} << (log2_w + log2_h));
}
// The bytes of the largest packed texture the console takes.
inline constexpr size_t kConsoleTextureBytes = kTexturePackHeader + 2 * size_t{kConsoleTextureTexels};

// Writes the packed texture into out; returns its size, or 0 when `capacity` is too small or a
// field is out of range (as unpack_texture checks it, without its texel limit).
size_t pack_texture(uint8_t log2_w, uint8_t log2_h, uint8_t format, const uint16_t* texels, uint8_t* out,
                    size_t capacity);

struct UnpackedTexture {
  uint8_t log2_width = 0, log2_height = 0, format = 0;
  uint8_t* texels = nullptr;  // into the packed bytes, at offset kTexturePackHeader
};

// Checks the magic, the version, the sides (8..256 texels each), the format (a 16-bit one), the
// zero bytes, at most max_texels texels and the size being exactly header + texels; returns nullptr
// and fills `out`, or a message saying what is wrong.
const char* unpack_texture(uint8_t* bytes, size_t size, uint32_t max_texels, UnpackedTexture* out);

}  // namespace htx::render
