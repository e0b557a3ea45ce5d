// Clipping in homogeneous clip space (Sutherland-Hodgman) against the six frustum planes
// x >= -w, x <= w, y >= -w, y <= w, z >= -w, z <= w, the same planes and order as the host's
// double-precision geometry stage (hw/model geometry.hpp).
#pragma once

#include <stdint.h>

namespace htx::render {

// A vertex in clip space with the attributes the clipper interpolates.
struct ClipVert {
  int32_t x, y, z, w;  // Q16.16
  int32_t s, t;        // normalised texture coordinates, Q16.16
  int32_t c[4];        // r, g, b, a in units of 2^-16 of one 8-bit step (0 .. 255 * 2^16)
};

// A triangle clipped against six planes has at most 3 + 6 vertices.
inline constexpr int kMaxClipVerts = 9;

struct ClipPolygon {
  int count;
  ClipVert v[kMaxClipVerts];
};

// Bit p set when the vertex is outside plane p (0..5 as above); bit 6 when w <= 0 (then it is also
// outside some plane). A vertex with outcode 0 has w > 0 and may be projected.
inline constexpr uint32_t kOutcodePlanes = 0x3F;
inline constexpr uint32_t kOutcodeBehind = 0x40;
inline uint32_t outcode(const ClipVert& v) {
  // Compared as x < -w rather than w + x < 0: no 64-bit sums on the per-vertex path. -w wraps only
  // for w = INT32_MIN, which bit 6 (w <= 0) catches anyway.
  const int32_t w = v.w, nw = static_cast<int32_t>(0u - static_cast<uint32_t>(w));
  return static_cast<uint32_t>(v.x < nw) | (static_cast<uint32_t>(v.x > w) << 1) |
         (static_cast<uint32_t>(v.y < nw) << 2) | (static_cast<uint32_t>(v.y > w) << 3) |
         (static_cast<uint32_t>(v.z < nw) << 4) | (static_cast<uint32_t>(v.z > w) << 5) |
         (static_cast<uint32_t>(w <= 0) << 6);
}

enum ClipResult : int {
  kClipOk = 0,
  // The polygon would have had more than kMaxClipVerts vertices, which only a triangle a few ulps
  // of clip space across can reach (rounded cut points make it non-convex): dropped whole.
  kClipTooManyVertices = 1,
};

// Clips `poly` in place against the planes in `planes` (bit p = plane p; bit 6 ignored), in plane order. A new
// vertex is interpolated from the inside end of its edge towards the outside end, so an edge shared
// by two triangles is cut at the same point in both. Afterwards count is 0 (nothing left) or >= 3,
// and every vertex has w > 0: a polygon that would keep a vertex with w <= 0 (only possible for a
// degenerate input at the eye) is dropped whole, as is one that would not fit (kClipTooManyVertices).
ClipResult clip_polygon(ClipPolygon* poly, uint32_t planes);

}  // namespace htx::render
