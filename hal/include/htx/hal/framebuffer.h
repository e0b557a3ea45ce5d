// Framebuffer readback: colour (RGB565, one pixel per half-word) and depth (one word per pixel)
// windows of docs/contracts.md, addressed by pixel index y * stride + x. Where the GPU has several
// colour pages (double or triple buffering, docs/video.md), the colour reads are of the page the raster
// unit draws into (FB_PAGE.DRAW), which holds the frame drawn last.
#pragma once

#include <stdint.h>

#include "htx/hal/regs.h"

namespace htx::hal {

inline constexpr uint32_t kFbColorBase = 0x30000000u;
inline constexpr uint32_t kFbDepthBase = 0x30100000u;
inline constexpr uint32_t kFbWindowBytes = 0x00100000u;

// Colour pages (RASTER.FB_MEM.PAGES: 1, or 2 or 3 for double or triple buffering) and the pixels of each.
inline uint32_t fb_pages() {
  return (HTX_RASTER->FB_MEM & RASTER_FB_MEM_PAGES_Msk) >> RASTER_FB_MEM_PAGES_Pos;
}
inline uint32_t fb_page_pixels() {
  return (HTX_RASTER->FB_MEM & RASTER_FB_MEM_PIXELS_Msk) >> RASTER_FB_MEM_PIXELS_Pos;
}

// The colour page fragments and the fast clear write. It applies to triangles already queued
// too, so set it while the raster unit is idle (a unit with one page ignores it).
inline void fb_set_draw_page(uint32_t page) {
  HTX_RASTER->FB_PAGE = (page << RASTER_FB_PAGE_DRAW_Pos) & RASTER_FB_PAGE_DRAW_Msk;
}
inline uint32_t fb_draw_page() {
  return (HTX_RASTER->FB_PAGE & RASTER_FB_PAGE_DRAW_Msk) >> RASTER_FB_PAGE_DRAW_Pos;
}

// The colour window's pixel index of the draw page's first pixel.
inline uint32_t fb_draw_page_first_pixel() {
  return fb_draw_page() * fb_page_pixels();
}

// A pixel of the draw page. (x, y) must lie in the page (not checked: this is the checksum's
// inner loop); past it the index reaches the next page, or beyond the colour window the depth window.
inline uint16_t fb_read_pixel(uint32_t stride, uint32_t x, uint32_t y) {
  const uint32_t i = fb_draw_page_first_pixel() + y * stride + x;
  const uint32_t word = backend::mem_read32(kFbColorBase + 4u * (i >> 1));
  return static_cast<uint16_t>(word >> (16u * (i & 1u)));
}

// Reads n colour pixels of row y from column x0 (word reads, two pixels each; a frame's checksum
// reads every pixel, so the whole words go in a loop of their own).
inline void fb_read_row(uint32_t stride, uint32_t y, uint32_t x0, uint32_t n, uint16_t* out) {
  uint32_t i = fb_draw_page_first_pixel() + y * stride + x0;
  const uint32_t end = i + n;
  if ((i & 1u) && i < end) {  // an odd first pixel: the high half of its word
    *out++ = static_cast<uint16_t>(backend::mem_read32(kFbColorBase + 4u * (i >> 1)) >> 16);
    ++i;
  }
  for (; i < end && end - i >= 2u; i += 2u, out += 2) {
    const uint32_t word = backend::mem_read32(kFbColorBase + 2u * i);
    out[0] = static_cast<uint16_t>(word);
    out[1] = static_cast<uint16_t>(word >> 16);
  }
  if (i < end) *out = static_cast<uint16_t>(backend::mem_read32(kFbColorBase + 2u * i));  // an even last pixel
}

inline uint32_t fb_read_depth(uint32_t stride, uint32_t x, uint32_t y) {
  return backend::mem_read32(kFbDepthBase + 4u * (y * stride + x));
}

}  // namespace htx::hal
