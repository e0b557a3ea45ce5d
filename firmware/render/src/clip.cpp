#include "htx/render/clip.h"

#include "htx/render/fixed.h"

namespace htx::render {

namespace {

// Signed distance-like value of v to plane p (inside when >= 0); 64 bits, since w +- x may leave
// the int32 range.
int64_t distance(const ClipVert& v, int p) {
  switch (p) {
    case 0: return static_cast<int64_t>(v.w) + v.x;
    case 1: return static_cast<int64_t>(v.w) - v.x;
    case 2: return static_cast<int64_t>(v.w) + v.y;
    case 3: return static_cast<int64_t>(v.w) - v.y;
    case 4: return static_cast<int64_t>(v.w) + v.z;
    default: return static_cast<int64_t>(v.w) - v.z;
  }
}

// t = num / den in Q2.30 for 0 <= num < den (the edge parameter of the crossing point). Both are
// first scaled so den fits 32 bits, then one 64/32-bit division.
int32_t edge_fraction_q30(int64_t num, int64_t den) {
  while (den >= (int64_t{1} << 31)) {
    num >>= 1;
    den >>= 1;
  }
  return static_cast<int32_t>((static_cast<uint64_t>(num) << 30) / static_cast<uint64_t>(den));
}

int32_t mix(int32_t a, int32_t b, int32_t t30) {
  return saturate32(a + round_shift((static_cast<int64_t>(b) - a) * t30, 30));
}

ClipVert intersect(const ClipVert& in, const ClipVert& out, int p) {
  const int64_t di = distance(in, p);
  const int64_t d_o = distance(out, p);
  const int32_t t = edge_fraction_q30(di, di - d_o);
  ClipVert r;
  r.x = mix(in.x, out.x, t);
  r.y = mix(in.y, out.y, t);
  r.z = mix(in.z, out.z, t);
  r.w = mix(in.w, out.w, t);
  r.s = mix(in.s, out.s, t);
  r.t = mix(in.t, out.t, t);
  for (int k = 0; k < 4; ++k) r.c[k] = mix(in.c[k], out.c[k], t);
  return r;
}

// Clips against plane p; false (the polygon emptied) when the result would not fit ClipPolygon.
bool clip_plane(ClipPolygon* poly, int p) {
  // A convex polygon crossed by a plane gains at most one vertex. Cut points are rounded, though,
  // so a polygon a few ulps across can turn non-convex and cross a later plane several times:
  // each vertex then gives at most two (itself and a cut point).
  ClipVert out[2 * kMaxClipVerts];
  int n = 0;
  const int count = poly->count;
  for (int i = 0; i < count; ++i) {
    const ClipVert& cur = poly->v[i];
    const ClipVert& next = poly->v[i + 1 == count ? 0 : i + 1];
    const bool cur_in = distance(cur, p) >= 0;
    const bool next_in = distance(next, p) >= 0;
    if (cur_in) out[n++] = cur;
    if (cur_in != next_in) out[n++] = cur_in ? intersect(cur, next, p) : intersect(next, cur, p);
  }
  if (n > kMaxClipVerts) {
    poly->count = 0;
    return false;
  }
  for (int i = 0; i < n; ++i) poly->v[i] = out[i];
  poly->count = n;
  return true;
}

}  // namespace

ClipResult clip_polygon(ClipPolygon* poly, uint32_t planes) {
  for (int p = 0; p < 6 && poly->count >= 3; ++p)
    if ((planes & (1u << p)) && !clip_plane(poly, p)) return kClipTooManyVertices;
  if (poly->count < 3) {
    poly->count = 0;
    return kClipOk;
  }
  for (int i = 0; i < poly->count; ++i)
    if (poly->v[i].w <= 0) {
      poly->count = 0;
      return kClipOk;
    }
  return kClipOk;
}

}  // namespace htx::render
