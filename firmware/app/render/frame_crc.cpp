#include "frame_crc.hpp"

#include "htx/hal/framebuffer.h"

namespace render_app {
namespace {

// Half-byte table: 16 words instead of 256 keep the RAM for scenes (the frame has 19,200 pixels, so
// two table steps per byte cost little).
constexpr uint32_t kNibble[16] = {0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu, 0x76DC4190u, 0x6B6B51F4u,
                                  0x4DB26158u, 0x5005713Cu, 0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu,
                                  0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu};

uint32_t crc_byte(uint32_t crc, uint32_t byte) {
  crc ^= byte;
  crc = (crc >> 4) ^ kNibble[crc & 0xFu];
  return (crc >> 4) ^ kNibble[crc & 0xFu];
}

}  // namespace

uint32_t frame_crc32(uint32_t width, uint32_t height) {
  uint32_t crc = 0xFFFFFFFFu;
  uint16_t row[256];
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x0 = 0; x0 < width; x0 += 256) {
      const uint32_t n = width - x0 < 256 ? width - x0 : 256;
      htx::hal::fb_read_row(width, y, x0, n, row);
      for (uint32_t i = 0; i < n; ++i) {
        crc = crc_byte(crc, row[i] & 0xFFu);
        crc = crc_byte(crc, row[i] >> 8);
      }
    }
  }
  return ~crc;
}

}  // namespace render_app
