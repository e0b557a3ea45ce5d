// docs/texture.md's "Memory layout", written here from the document and not from the uploader
// (hal texture.h), for the tests that check where texels land: the texture window's base, and the
// word of texel (i, j) of level `level` of a 2^lw0 x 2^lh0 chain at base block `base` (levels one
// after the other, each row-major in 2x2 blocks of four consecutive words).
#pragma once

#include <algorithm>
#include <cstdint>

namespace htx::test {

inline constexpr uint32_t kDocTextureWindow = 0x40000000u;

inline uint32_t doc_word(uint32_t base, unsigned lw0, unsigned lh0, unsigned level, uint32_t i, uint32_t j) {
  uint32_t offset = 0;
  for (unsigned l = 0; l < level; ++l) {
    const uint32_t w = std::max(1u, (1u << lw0) >> l), h = std::max(1u, (1u << lh0) >> l);
    offset += std::max(1u, w / 2) * std::max(1u, h / 2);
  }
  const uint32_t wl = std::max(1u, (1u << lw0) >> level);
  return 4 * (base + offset + (j >> 1) * std::max(1u, wl / 2) + (i >> 1)) + 2 * (j & 1) + (i & 1);
}

}  // namespace htx::test
