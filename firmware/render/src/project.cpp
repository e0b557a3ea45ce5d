#include "htx/render/project.h"

namespace htx::render {

namespace {

// c / w in Q2.29 from c (Q16.16) and the reciprocal of w_raw: c/w = c_raw * mant * 2^(lz - 63).
// c is clamped to [-w, w] (a cut point may lie a few ulps outside its plane) and normalised by
// 2^(lz - 2), which then fits 32 bits since w_raw < 2^(32 - lz); one signed-by-unsigned high
// product gives the Q29 value.
inline int32_t divide_q29(int32_t c, int32_t w, int sh, uint32_t mant) {
  if (c > w) c = w;
  if (c < -w) c = -w;
  const int32_t cn = sh >= 0 ? shift_left(c, sh) : c >> -sh;
  return static_cast<int32_t>((static_cast<int64_t>(cn) * static_cast<int64_t>(mant)) >> 32);
}

// round(ndc29 * size / 2^22) = round((ndc + 1) * size * 128) - size * 128.
inline int32_t to_subpixels(int32_t ndc29, int32_t size) {
  const int64_t p = static_cast<int64_t>(ndc29) * (size << 10);
  return static_cast<int32_t>((p + 0x80000000ll) >> 32);
}

}  // namespace

void project(const ClipVert& v, const Viewport& vp, ScreenVert* s) {
  const Reciprocal r = reciprocal(static_cast<uint32_t>(v.w));
  s->inv_w = r;
  const int sh = r.lz - 2;
  const int32_t nx = divide_q29(v.x, v.w, sh, r.mant);
  const int32_t ny = divide_q29(v.y, v.w, sh, r.mant);
  const int32_t nz = divide_q29(v.z, v.w, sh, r.mant);
  // Subpixel x = (ndc + 1) * width * 128 (y flipped: (1 - ndc) * height * 128).
  s->x = to_subpixels(nx, vp.width) + (vp.width << 7);
  s->y = to_subpixels(-ny, vp.height) + (vp.height << 7);
  // z = (ndc + 1) / 2 as a 0.32 fraction = (ndc29 + 2^29) * 4, clamped at both ends: ndc29 can be
  // a unit beyond [-2^29, 2^29] at the planes (the reciprocal may be a unit above 1/w), and the
  // near plane must not wrap to the far end.
  const int32_t z = nz + (int32_t{1} << 29);
  s->z = z <= 0 ? 0u : z >= (int32_t{1} << 30) ? 0xFFFFFFFFu : static_cast<uint32_t>(z) << 2;
  s->w = v.w;
  s->attr = &v;
}

int64_t screen_area2(const ScreenVert& a, const ScreenVert& b, const ScreenVert& c) {
  return (static_cast<int64_t>(b.x) - a.x) * (static_cast<int64_t>(c.y) - a.y) -
         (static_cast<int64_t>(c.x) - a.x) * (static_cast<int64_t>(b.y) - a.y);
}

}  // namespace htx::render
