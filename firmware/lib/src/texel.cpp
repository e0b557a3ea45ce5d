#include "htx/fw/texel.h"

namespace htx::fw {

uint32_t encode_texel(uint8_t format, uint32_t c) {
  const uint32_t r = c & 0xFFu, g = (c >> 8) & 0xFFu, b = (c >> 16) & 0xFFu, a = c >> 24;
  switch (format) {
    case kTexelRgb565: return (quantise_channel(r, 5) << 11) | (quantise_channel(g, 6) << 5) | quantise_channel(b, 5);
    case kTexelRgba4444:
      return (quantise_channel(r, 4) << 12) | (quantise_channel(g, 4) << 8) | (quantise_channel(b, 4) << 4) |
             quantise_channel(a, 4);
    case kTexelRgba8888: return c;
    default: return 0;
  }
}

uint32_t decode_texel(uint8_t format, uint32_t t) {
  switch (format) {
    case kTexelRgb565:
      return widen_channel((t >> 11) & 31u, 5) | (widen_channel((t >> 5) & 63u, 6) << 8) |
             (widen_channel(t & 31u, 5) << 16) | (0xFFu << 24);
    case kTexelRgba4444:
      return widen_channel((t >> 12) & 15u, 4) | (widen_channel((t >> 8) & 15u, 4) << 8) |
             (widen_channel((t >> 4) & 15u, 4) << 16) | (widen_channel(t & 15u, 4) << 24);
    case kTexelRgba8888: return t;
    default: return 0;
  }
}

}  // namespace htx::fw
