#include "htx/fw/rle16.h"

namespace htx::fw {

namespace {
void put_pixel(uint8_t* out, uint16_t p) {
  out[0] = static_cast<uint8_t>(p);
  out[1] = static_cast<uint8_t>(p >> 8);
}
}  // namespace

size_t rle16_encode(const uint16_t* pixels, size_t n, uint8_t* out) {
  size_t i = 0, o = 0;
  while (i < n) {
    size_t run = 1;
    while (i + run < n && run < 129 && pixels[i + run] == pixels[i]) ++run;
    if (run >= 2) {
      out[o++] = static_cast<uint8_t>(0x80 + run - 2);
      put_pixel(out + o, pixels[i]);
      o += 2;
      i += run;
      continue;
    }
    // Literals up to the next pair of equal pixels (or 128 of them).
    size_t lit = 1;
    while (i + lit < n && lit < 128 && !(i + lit + 1 < n && pixels[i + lit] == pixels[i + lit + 1])) ++lit;
    out[o++] = static_cast<uint8_t>(lit - 1);
    for (size_t k = 0; k < lit; ++k, o += 2) put_pixel(out + o, pixels[i + k]);
    i += lit;
  }
  return o;
}

long rle16_decode(const uint8_t* code, size_t size, uint16_t* pixels, size_t capacity) {
  size_t i = 0, o = 0;
  while (i < size) {
    const uint8_t c = code[i++];
    const bool repeat = c >= 0x80;
    const size_t count = repeat ? c - 0x80 + 2u : c + 1u;
    const size_t bytes = repeat ? 2 : 2 * count;
    if (i + bytes > size || o + count > capacity) return -1;
    for (size_t k = 0; k < count; ++k) {
      const size_t at = repeat ? i : i + 2 * k;
      pixels[o++] = static_cast<uint16_t>(code[at] | (code[at + 1] << 8));
    }
    i += bytes;
  }
  return static_cast<long>(o);
}

}  // namespace htx::fw
