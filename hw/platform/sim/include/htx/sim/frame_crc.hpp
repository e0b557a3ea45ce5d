// CRC-32 of a frame of RGB565 pixels, the checksum the render firmware prints and `htx sim --json`
// reports as frame_crc32: IEEE 802.3 (reflected 0xEDB88320, initial and final 0xFFFFFFFF, zlib's
// crc32) over the pixels in order, each as two bytes, low byte first.
#pragma once

#include <cstdint>
#include <vector>

namespace htx::sim {

uint32_t frame_crc32(const std::vector<uint16_t>& pixels);

}  // namespace htx::sim
