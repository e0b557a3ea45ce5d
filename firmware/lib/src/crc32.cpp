#include "htx/fw/crc32.h"

namespace htx::fw {

namespace {
constexpr uint32_t kNibble[16] = {0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu, 0x76DC4190u, 0x6B6B51F4u,
                                  0x4DB26158u, 0x5005713Cu, 0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu,
                                  0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu};
}  // namespace

uint32_t crc32_update_byte(uint32_t reg, uint8_t byte) {
  reg ^= byte;
  reg = (reg >> 4) ^ kNibble[reg & 0xFu];
  return (reg >> 4) ^ kNibble[reg & 0xFu];
}

uint32_t crc32_update(uint32_t reg, const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) reg = crc32_update_byte(reg, data[i]);
  return reg;
}

}  // namespace htx::fw
