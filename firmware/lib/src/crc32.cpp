#include "htx/fw/crc32.h"

namespace htx::fw {

namespace {

// The byte table, built by the compiler: entry b is the register's change for the byte b
// (eight steps of the reflected polynomial). 1 KiB of RAM for a frame's checksum twice as fast as
// the half-byte table's two lookups a byte (render.elf: 26 -> 13 clocks a byte).
struct ByteTable {
  uint32_t entry[256];
  constexpr ByteTable() : entry() {
    for (uint32_t b = 0; b < 256; ++b) {
      uint32_t r = b;
      for (int k = 0; k < 8; ++k) r = (r >> 1) ^ ((r & 1u) ? 0xEDB88320u : 0u);
      entry[b] = r;
    }
  }
};
constexpr ByteTable kTable;

}  // namespace

uint32_t crc32_update_byte(uint32_t reg, uint8_t byte) { return (reg >> 8) ^ kTable.entry[(reg ^ byte) & 0xFFu]; }

uint32_t crc32_update(uint32_t reg, const uint8_t* data, size_t size) {
  if (size == 0) return reg;
  // Two bytes a turn where it can, and the branch at the bottom: -Os otherwise tests at the top
  // and jumps back, a predicted jump's bubble a byte. The step is written out, as in
  // crc32_update_byte: through an inlined helper -Os orders it with one more load-use stall
  // (render.elf's checksums 1.08 M clocks against 1.04 M).
  const uint8_t* const end = data + size;
  if (size & 1u) reg = (reg >> 8) ^ kTable.entry[(reg ^ *data++) & 0xFFu];
  while (data != end) {
    reg = (reg >> 8) ^ kTable.entry[(reg ^ data[0]) & 0xFFu];
    reg = (reg >> 8) ^ kTable.entry[(reg ^ data[1]) & 0xFFu];
    data += 2;
  }
  return reg;
}

}  // namespace htx::fw
