// Texture unit driver (hw/regs/texture.json, docs/texture.md): capabilities, descriptors, the
// texture memory window and its layout, status, errors and counters.
//
// Memory layout (docs/texture.md, "Memory layout"): one texel per 32-bit word of the window at
// 0x4000_0000; a texture whose descriptor BASE is block B stores its levels one after the other,
// each row-major in 2x2 blocks of four consecutive words:
//   word(L, i, j) = 4 * (B + offset(L) + (j >> 1) * max(1, w_L / 2) + (i >> 1)) + 2 * (j & 1) + (i & 1)
#pragma once

#include <stdint.h>

#include "htx/hal/raster.h"
#include "htx/hal/regs.h"

namespace htx::hal {

inline constexpr uint32_t kTexWindowBase = 0x40000000u;
inline constexpr uint32_t kTexWindowBytes = 0x00100000u;
inline constexpr uint32_t kTexMaxSlots = 8;  // TEX0..TEX7

struct TextureCaps {
  uint32_t formats = 0;     // bit i = format i (0 RGB565, 1 RGBA4444, 2 RGBA8888)
  uint32_t filters = 0;     // bit i = filter i (0 nearest, 1 bilinear, 2 trilinear)
  bool counters = false;    // CNT_SAMPLES / CNT_BUSY are built
  uint32_t slots = 0;       // descriptors built
  uint32_t block_bits = 0;  // log2 of the 2x2 blocks the memory holds
  uint32_t texel_bits = 0;  // 16, or 32 with RGBA8888
  bool window_read = false; // the memory window can be read back (not on the board: written only)
};

inline TextureCaps texture_caps() {
  const uint32_t c = HTX_TEXTURE->CAPS;
  TextureCaps t;
  t.formats = (c & TEXTURE_CAPS_FORMATS_Msk) >> TEXTURE_CAPS_FORMATS_Pos;
  t.filters = (c & TEXTURE_CAPS_FILTERS_Msk) >> TEXTURE_CAPS_FILTERS_Pos;
  t.counters = (c & TEXTURE_CAPS_COUNTERS_Msk) != 0;
  t.slots = (c & TEXTURE_CAPS_SLOTS_Msk) >> TEXTURE_CAPS_SLOTS_Pos;
  t.block_bits = (c & TEXTURE_CAPS_BLOCK_BITS_Msk) >> TEXTURE_CAPS_BLOCK_BITS_Pos;
  t.texel_bits = (c & TEXTURE_CAPS_TEXEL_BITS_Msk) >> TEXTURE_CAPS_TEXEL_BITS_Pos;
  t.window_read = (c & TEXTURE_CAPS_WINDOW_READ_Msk) != 0;
  return t;
}

// Blocks (2x2 texels) of level `level` of a 2^log2_w x 2^log2_h chain, and of all levels before it.
inline uint32_t texture_level_blocks(uint32_t log2_w, uint32_t log2_h, uint32_t level) {
  const uint32_t bw = log2_w > level + 1 ? log2_w - level - 1 : 0, bh = log2_h > level + 1 ? log2_h - level - 1 : 0;
  return 1u << (bw + bh);
}
inline uint32_t texture_level_offset(uint32_t log2_w, uint32_t log2_h, uint32_t level) {
  uint32_t off = 0;
  for (uint32_t l = 0; l < level; ++l) off += texture_level_blocks(log2_w, log2_h, l);
  return off;
}
// Blocks of the whole chain (levels down to 1x1).
inline uint32_t texture_chain_blocks(uint32_t log2_w, uint32_t log2_h) {
  return texture_level_offset(log2_w, log2_h, (log2_w > log2_h ? log2_w : log2_h) + 1);
}

// Word index (byte offset / 4 in the window) of texel (i, j) of `level` of the chain at base_block.
inline uint32_t texture_word_index(uint32_t base_block, uint32_t log2_w, uint32_t log2_h, uint32_t level, uint32_t i,
                                   uint32_t j) {
  const uint32_t lw = log2_w > level ? log2_w - level : 0;
  const uint32_t row_blocks = lw > 0 ? 1u << (lw - 1) : 1u;
  const uint32_t block = base_block + texture_level_offset(log2_w, log2_h, level) + (j >> 1) * row_blocks + (i >> 1);
  return 4u * block + 2u * (j & 1u) + (i & 1u);
}

// Writes the texels of one level (row-major, 2^lw x 2^lh of the level) into the window. Words
// beyond the window are not written; returns false if the level does not fit in it.
inline bool texture_write_level(uint32_t base_block, uint32_t log2_w, uint32_t log2_h, uint32_t level,
                                const uint32_t* texels) {
  const uint32_t lw = log2_w > level ? log2_w - level : 0, lh = log2_h > level ? log2_h - level : 0;
  const uint32_t w = 1u << lw, h = 1u << lh;
  const uint32_t end_block =
      base_block + texture_level_offset(log2_w, log2_h, level) + texture_level_blocks(log2_w, log2_h, level);
  if (16u * end_block > kTexWindowBytes) return false;
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i)
      backend::mem_write32(kTexWindowBase + 4u * texture_word_index(base_block, log2_w, log2_h, level, i, j),
                           texels[j * w + i]);
  return true;
}

inline void texture_write_texel(uint32_t base_block, uint32_t log2_w, uint32_t log2_h, uint32_t level, uint32_t i,
                                uint32_t j, uint32_t texel) {
  backend::mem_write32(kTexWindowBase + 4u * texture_word_index(base_block, log2_w, log2_h, level, i, j), texel);
}

// Only where TextureCaps::window_read: the board's texture memory is written only (a read of it is a
// bus error).
inline uint32_t texture_read_texel(uint32_t base_block, uint32_t log2_w, uint32_t log2_h, uint32_t level, uint32_t i,
                                   uint32_t j) {
  return backend::mem_read32(kTexWindowBase + 4u * texture_word_index(base_block, log2_w, log2_h, level, i, j));
}

// The descriptor register of a slot (TEX0 + 4 * slot); slot < kTexMaxSlots.
inline auto& texture_descriptor_reg(uint32_t slot) { return (&HTX_TEXTURE->TEX0)[slot]; }

inline uint32_t texture_descriptor_word(uint32_t base_block, uint32_t log2_w, uint32_t log2_h, uint32_t format) {
  return ((base_block << TEXTURE_TEX0_BASE_Pos) & TEXTURE_TEX0_BASE_Msk) |
         ((log2_w << TEXTURE_TEX0_LOG2_WIDTH_Pos) & TEXTURE_TEX0_LOG2_WIDTH_Msk) |
         ((log2_h << TEXTURE_TEX0_LOG2_HEIGHT_Pos) & TEXTURE_TEX0_LOG2_HEIGHT_Msk) |
         ((format << TEXTURE_TEX0_FORMAT_Pos) & TEXTURE_TEX0_FORMAT_Msk);
}

enum TextureStatus : int {
  kTextureOk = 0,
  kTextureBadSlot = 1,    // slot >= CAPS.SLOTS (the unit takes slot numbers modulo its count)
  kTextureBadSize = 2,    // log2 side outside 3..8
  kTextureBadFormat = 3,  // a format the unit does not build (CAPS.FORMATS)
  kTextureBadBase = 4,    // base block beyond the 16-bit BASE field
  kTextureTooLarge = 5,   // the chain runs past the unit's memory (2^CAPS.BLOCK_BITS blocks, at most the window)
  kTextureTimeout = 6,    // the unit stayed busy
};

// Checks a texture's placement against what this unit builds (CAPS): the slot, the sizes, the
// format, the base and that the whole chain fits its memory. The board's unit has 4 slots, 16-bit
// formats and 1,024 blocks: a slot beyond them would point another slot's texture, and a texel
// written past the memory ends in a bus error (a store fault).
inline TextureStatus texture_check(uint32_t slot, uint32_t base_block, uint32_t log2_w, uint32_t log2_h,
                                   uint32_t format) {
  const TextureCaps caps = texture_caps();
  if (slot >= kTexMaxSlots || slot >= caps.slots) return kTextureBadSlot;
  if (log2_w < 3 || log2_w > 8 || log2_h < 3 || log2_h > 8) return kTextureBadSize;
  if (format > 2 || !((caps.formats >> format) & 1u)) return kTextureBadFormat;
  if (base_block > (TEXTURE_TEX0_BASE_Msk >> TEXTURE_TEX0_BASE_Pos)) return kTextureBadBase;
  const uint32_t end = base_block + texture_chain_blocks(log2_w, log2_h);
  if (16u * end > kTexWindowBytes || (caps.block_bits < 32 && end > (1u << caps.block_bits))) return kTextureTooLarge;
  return kTextureOk;
}

inline bool texture_busy() { return (HTX_TEXTURE->STATUS & TEXTURE_STATUS_BUSY_Msk) != 0; }

// Polls STATUS until no request is in flight, at most max_polls times; false on a timeout.
inline bool texture_wait_idle(uint32_t max_polls) {
  for (uint32_t i = 0; i < max_polls; ++i)
    if (!texture_busy()) return true;
  return false;
}

// Points a slot at a chain. A descriptor may change only while no textured triangle is drawn
// (TEXn's description): the raster unit's BUSY covers all of a triangle's fragments, the texture
// unit's can fall between two of them, so both are waited for (up to max_polls polls each).
inline TextureStatus texture_set_descriptor(uint32_t slot, uint32_t base_block, uint32_t log2_w, uint32_t log2_h,
                                            uint32_t format, uint32_t max_polls) {
  const TextureStatus st = texture_check(slot, base_block, log2_w, log2_h, format);
  if (st != kTextureOk) return st;
  if (!raster_wait_idle(max_polls) || !texture_wait_idle(max_polls)) return kTextureTimeout;
  texture_descriptor_reg(slot) = texture_descriptor_word(base_block, log2_w, log2_h, format);
  return kTextureOk;
}

// Sticky error flags (STATUS.ERR_FORMAT, ERR_FILTER) since the last clear.
inline uint32_t texture_errors() {
  return HTX_TEXTURE->STATUS & (TEXTURE_STATUS_ERR_FORMAT_Msk | TEXTURE_STATUS_ERR_FILTER_Msk);
}
inline void texture_clear_errors() {
  HTX_TEXTURE->STATUS = TEXTURE_STATUS_ERR_FORMAT_Msk | TEXTURE_STATUS_ERR_FILTER_Msk;
}

inline void texture_reset_counters() { HTX_TEXTURE->CNT_RESET = TEXTURE_CNT_RESET_RESET_Msk; }
inline uint32_t texture_samples() { return HTX_TEXTURE->CNT_SAMPLES; }
inline uint32_t texture_busy_cycles() { return HTX_TEXTURE->CNT_BUSY; }

}  // namespace htx::hal
