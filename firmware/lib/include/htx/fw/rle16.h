// Run-length code of 16-bit pixels for frame downloads (docs/console.md): a control byte c, then
// for c < 0x80 the next c + 1 pixels as they are, for c >= 0x80 one pixel repeated c - 0x80 + 2
// times. A pixel is two bytes, low byte first. Freestanding C++17.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace htx::fw {

// The most bytes rle16_encode writes for n pixels.
inline constexpr size_t rle16_max_size(size_t n) { return 2 * n + (n + 127) / 128; }

// Codes n pixels into out (at least rle16_max_size(n) bytes); returns the bytes written.
size_t rle16_encode(const uint16_t* pixels, size_t n, uint8_t* out);

// Decodes `size` bytes into at most `capacity` pixels; returns the pixel count, or -1 when the code
// is truncated or would write more than `capacity` pixels.
long rle16_decode(const uint8_t* code, size_t size, uint16_t* pixels, size_t capacity);

}  // namespace htx::fw
