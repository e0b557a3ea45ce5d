#include "htx/rtl/texture_layout.hpp"

#include "htx/model/texture.hpp"
#include "htx_regs.h"

namespace htx::rtl {

namespace {

// Blocks before level `level` of a 2^a x 2^b chain.
uint32_t level_offset(unsigned a, unsigned b, unsigned level) {
  uint32_t off = 0;
  for (unsigned l = 0; l < level; ++l) {
    const unsigned sa = a > l + 1 ? a - l - 1 : 0, sb = b > l + 1 ? b - l - 1 : 0;
    off += uint32_t{1} << (sa + sb);
  }
  return off;
}

}  // namespace

uint32_t texture_chain_blocks(const Texture& tex) {
  return level_offset(tex.log2_width, tex.log2_height, level_count(tex));
}

void append_texture_words(const Texture& tex, uint32_t base_block, uint32_t window_base,
                          std::vector<std::pair<uint32_t, uint32_t>>& out) {
  const unsigned n = level_count(tex);
  for (unsigned l = 0; l < n; ++l) {
    const unsigned lw = level_log2_width(tex, l), lh = level_log2_height(tex, l);
    const uint32_t w = uint32_t{1} << lw, h = uint32_t{1} << lh;
    const uint32_t stride = lw > 0 ? w / 2 : 1;  // blocks per block row
    const uint32_t first = base_block + level_offset(tex.log2_width, tex.log2_height, l);
    for (uint32_t j = 0; j < h; ++j)
      for (uint32_t i = 0; i < w; ++i) {
        const uint32_t word = 4 * (first + (j >> 1) * stride + (i >> 1)) + 2 * (j & 1) + (i & 1);
        out.emplace_back(window_base + 4 * word, tex.levels[l][j * w + i]);
      }
  }
}

uint32_t texture_descriptor(const Texture& tex, uint32_t base_block) {
  return ((base_block << TEXTURE_TEX0_BASE_Pos) & TEXTURE_TEX0_BASE_Msk) |
         ((tex.log2_width << TEXTURE_TEX0_LOG2_WIDTH_Pos) & TEXTURE_TEX0_LOG2_WIDTH_Msk) |
         ((tex.log2_height << TEXTURE_TEX0_LOG2_HEIGHT_Pos) & TEXTURE_TEX0_LOG2_HEIGHT_Msk) |
         ((static_cast<uint32_t>(tex.format) << TEXTURE_TEX0_FORMAT_Pos) & TEXTURE_TEX0_FORMAT_Msk);
}

}  // namespace htx::rtl
