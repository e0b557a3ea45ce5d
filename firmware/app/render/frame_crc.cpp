#include "frame_crc.hpp"

#include "htx/fw/crc32.h"
#include "htx/hal/framebuffer.h"

namespace render_app {

uint32_t frame_crc32(uint32_t width, uint32_t height) {
  uint32_t reg = htx::fw::kCrc32Init;
  uint16_t row[256];
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x0 = 0; x0 < width; x0 += 256) {
      const uint32_t n = width - x0 < 256 ? width - x0 : 256;
      htx::hal::fb_read_row(width, y, x0, n, row);
      // The pixels' bytes in memory order, low byte first: the target is little-endian.
      reg = htx::fw::crc32_update(reg, reinterpret_cast<const uint8_t*>(row), 2 * n);
    }
  }
  return ~reg;
}

}  // namespace render_app
