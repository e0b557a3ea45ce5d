// Texture upload: a level-0 image encoded into its format, its whole mip chain generated (the box
// filter of htx/fw/mip_chain.h, bit-exact with the model) and written into the texture memory
// window through the HAL, then the slot's descriptor pointed at it.
#pragma once

#include <stdint.h>

#include "htx/hal/texture.h"

namespace htx::render {

struct TextureImage {
  const uint32_t* rgba8;   // 2^log2_width x 2^log2_height pixels, row-major (row 0 = v = 0), r in bits 7:0
  uint8_t log2_width = 6, log2_height = 6;  // 3..8 each
  uint8_t format = 0;      // 0 RGB565, 1 RGBA4444, 2 RGBA8888
};

// Scratch words upload_texture needs: level 1's texel count (max(1, w/2) * max(1, h/2)).
constexpr uint32_t texture_upload_scratch_words(uint32_t log2_w, uint32_t log2_h) {
  return (log2_w > 0 ? 1u << (log2_w - 1) : 1u) * (log2_h > 0 ? 1u << (log2_h - 1) : 1u);
}

enum UploadStatus : int {
  kUploadOk = 0,
  kUploadBadTexture = 1,     // hal::texture_check refused slot, size, format or placement (*hal_status says why)
  kUploadScratchTooSmall = 2,
  kUploadTimeout = 3,        // the raster or texture unit stayed busy (nothing, or not the descriptor, written)
};

// Uploads img's chain at base_block and points `slot` at it. Waits (max_polls STATUS reads each)
// for the raster unit to be idle before writing texels (no textured triangle in flight samples a
// half-written chain) and for the texture unit before writing the descriptor. Blocks used: hal::texture_chain_blocks.
UploadStatus upload_texture(uint32_t slot, uint32_t base_block, const TextureImage& img, uint32_t* scratch,
                            uint32_t scratch_words, uint32_t max_polls, hal::TextureStatus* hal_status = nullptr);

// The same for a level 0 given as texels of a 16-bit format (RGB565 or RGBA4444; anything else is
// kUploadBadTexture): 2^log2_w x 2^log2_h of them, two bytes each, little-endian, row-major, at
// `texels` (4-byte aligned). Needs no scratch: the buffer is overwritten. Level 1 is generated in
// place over level 0, level-1 texel k (one word) over level-0 texels 2k and 2k+1, which no level-1
// texel after k reads; the further levels in place as upload_texture's. The chain equals
// upload_texture's for the image these texels decode to.
UploadStatus upload_texture_texels16(uint32_t slot, uint32_t base_block, uint8_t log2_w, uint8_t log2_h,
                                     uint8_t format, uint8_t* texels, uint32_t max_polls,
                                     hal::TextureStatus* hal_status = nullptr);

}  // namespace htx::render
