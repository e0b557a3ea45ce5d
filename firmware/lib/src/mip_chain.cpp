#include "htx/fw/mip_chain.h"

#include "htx/fw/texel.h"

namespace htx::fw {

void mip_next_level(uint8_t format, const uint32_t* src, MipSource source, unsigned log2_w, unsigned log2_h,
                    uint32_t* dst) {
  if (!texel_format_valid(format)) return;
  const uint32_t cw = 1u << log2_w, ch = 1u << log2_h;
  const uint32_t nw = cw > 1 ? cw / 2 : 1, nh = ch > 1 ? ch / 2 : 1;
  const uint32_t fx = cw / nw, fy = ch / nh;  // 1 or 2 texels per axis in the box
  const uint32_t count = fx * fy;
  const uint32_t round = count / 2, shift = count == 4 ? 2 : (count == 2 ? 1 : 0);
  for (uint32_t j = 0; j < nh; ++j)
    for (uint32_t i = 0; i < nw; ++i) {
      uint32_t s[4] = {0, 0, 0, 0};
      for (uint32_t dy = 0; dy < fy; ++dy)
        for (uint32_t dx = 0; dx < fx; ++dx) {
          const uint32_t raw = src[(j * fy + dy) * cw + i * fx + dx];
          const uint32_t c =
              source == kMipSourceRgba8 ? decode_texel(format, encode_texel(format, raw)) : decode_texel(format, raw);
          s[0] += c & 0xFFu;
          s[1] += (c >> 8) & 0xFFu;
          s[2] += (c >> 16) & 0xFFu;
          s[3] += c >> 24;
        }
      const uint32_t box = ((s[0] + round) >> shift) | (((s[1] + round) >> shift) << 8) |
                           (((s[2] + round) >> shift) << 16) | (((s[3] + round) >> shift) << 24);
      dst[j * nw + i] = encode_texel(format, box);
    }
}

}  // namespace htx::fw
