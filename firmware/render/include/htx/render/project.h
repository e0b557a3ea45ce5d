// Perspective divide and viewport: one reciprocal of w per vertex, then x, y on the vertex-record
// grid of 1/256 pixel (origin top-left, y down), z in [0, 1] as an unsigned 0.32 fraction.
#pragma once

#include <stdint.h>

#include "htx/render/clip.h"
#include "htx/render/fixed.h"

namespace htx::render {

struct ScreenVert {
  int32_t x, y;      // 1/256 pixel
  uint32_t z;        // depth in [0, 1] * 2^32, saturated at 2^32 - 1
  int32_t w;         // clip w, Q16.16 (> 0)
  Reciprocal inv_w;      // 1/w_raw (w_raw = w in Q16.16 units)
  const ClipVert* attr;  // the clip vertex it came from: texture coordinates and colour
};

struct Viewport {
  int32_t width, height;  // pixels, 1..4096
};

// Projects a clip vertex with w > 0 (callers guarantee it: clip_polygon drops anything else, and
// outcode 0 implies it). Coordinates beyond +-w (cut points a few ulps outside) are clamped to it.
// out->attr points at v, which must outlive the use of *out.
void project(const ClipVert& v, const Viewport& vp, ScreenVert* out);

// Twice the signed screen area in (1/256 pixel)^2; negative for front faces (counter-clockwise in
// NDC, y down on screen), 0 for a degenerate triangle.
int64_t screen_area2(const ScreenVert& a, const ScreenVert& b, const ScreenVert& c);

}  // namespace htx::render
