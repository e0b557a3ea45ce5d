// Framebuffer readback: colour (RGB565, one pixel per half-word) and depth (one word per pixel)
// windows of docs/contracts.md, addressed by pixel index y * stride + x.
#pragma once

#include <stdint.h>

#include "htx/hal/regs.h"

namespace htx::hal {

inline constexpr uint32_t kFbColorBase = 0x30000000u;
inline constexpr uint32_t kFbDepthBase = 0x30100000u;
inline constexpr uint32_t kFbWindowBytes = 0x00100000u;

inline uint16_t fb_read_pixel(uint32_t stride, uint32_t x, uint32_t y) {
  const uint32_t i = y * stride + x;
  const uint32_t word = backend::mem_read32(kFbColorBase + 4u * (i >> 1));
  return static_cast<uint16_t>(word >> (16u * (i & 1u)));
}

// Reads n colour pixels of row y from column x0 (word reads, two pixels each).
inline void fb_read_row(uint32_t stride, uint32_t y, uint32_t x0, uint32_t n, uint16_t* out) {
  uint32_t i = y * stride + x0;
  const uint32_t end = i + n;
  while (i < end) {
    const uint32_t word = backend::mem_read32(kFbColorBase + 4u * (i >> 1));
    for (uint32_t half = i & 1u; half < 2u && i < end; ++half, ++i)
      *out++ = static_cast<uint16_t>(word >> (16u * half));
  }
}

inline uint32_t fb_read_depth(uint32_t stride, uint32_t x, uint32_t y) {
  return backend::mem_read32(kFbDepthBase + 4u * (y * stride + x));
}

}  // namespace htx::hal
