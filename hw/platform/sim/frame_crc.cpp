#include "htx/sim/frame_crc.hpp"

#include <array>

namespace htx::sim {
namespace {

std::array<uint32_t, 256> make_table() {
  std::array<uint32_t, 256> t{};
  for (uint32_t n = 0; n < 256; ++n) {
    uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ ((c & 1u) ? 0xEDB88320u : 0u);
    t[n] = c;
  }
  return t;
}

}  // namespace

uint32_t frame_crc32(const std::vector<uint16_t>& pixels) {
  static const std::array<uint32_t, 256> table = make_table();
  uint32_t crc = 0xFFFFFFFFu;
  for (uint16_t p : pixels) {
    crc = (crc >> 8) ^ table[(crc ^ p) & 0xFFu];
    crc = (crc >> 8) ^ table[(crc ^ (p >> 8)) & 0xFFu];
  }
  return ~crc;
}

}  // namespace htx::sim
