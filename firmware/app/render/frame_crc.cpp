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
      for (uint32_t i = 0; i < n; ++i) {
        reg = htx::fw::crc32_update_byte(reg, static_cast<uint8_t>(row[i] & 0xFFu));
        reg = htx::fw::crc32_update_byte(reg, static_cast<uint8_t>(row[i] >> 8));
      }
    }
  }
  return ~reg;
}

}  // namespace render_app
