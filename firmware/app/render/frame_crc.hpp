// CRC-32 of the frame in the colour window: IEEE 802.3 (reflected polynomial 0xEDB88320, initial
// and final value 0xFFFFFFFF, as zlib's crc32), over the RGB565 pixels row by row, each pixel as two
// bytes, low byte first. `htx sim --json` reports the same checksum as frame_crc32.
#pragma once

#include <stdint.h>

namespace render_app {

// Reads width x height pixels (stride = width) through the HAL's framebuffer window.
uint32_t frame_crc32(uint32_t width, uint32_t height);

}  // namespace render_app
