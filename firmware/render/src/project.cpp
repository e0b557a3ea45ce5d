#include "htx/render/project.h"

namespace htx::render {

namespace {

// c / w in Q2.30 (saturated to int32) from c (Q16.16) and the reciprocal of w_raw:
// c/w = c_raw * mant * 2^(lz - 63), so the Q30 value is that product shifted right by 33 - lz.
int32_t divide_q30(int32_t c, const Reciprocal& r) {
  const int64_t p = static_cast<int64_t>(c) * static_cast<int64_t>(r.mant);
  const int s = 33 - r.lz;  // lz <= 32 (w_raw >= 1), so s >= 1
  return saturate32(round_shift(p, s));
}

}  // namespace

ScreenVert project(const ClipVert& v, const Viewport& vp) {
  ScreenVert s;
  s.inv_w = reciprocal(static_cast<uint32_t>(v.w));
  const int32_t nx = divide_q30(v.x, s.inv_w);
  const int32_t ny = divide_q30(v.y, s.inv_w);
  const int32_t nz = divide_q30(v.z, s.inv_w);
  // Subpixel x = (ndc + 1) * width * 128 = ndc30 * width / 2^23 + width * 128 (y flipped).
  s.x = saturate32(round_shift(static_cast<int64_t>(nx) * vp.width, 23) + (int64_t{vp.width} << 7));
  s.y = saturate32(round_shift(-static_cast<int64_t>(ny) * vp.height, 23) + (int64_t{vp.height} << 7));
  // z = (ndc + 1) / 2 as a 0.32 fraction = (ndc30 + 2^30) * 2, clamped to [0, 1].
  const int64_t z = (static_cast<int64_t>(nz) + (int64_t{1} << 30)) * 2;
  s.z = z < 0 ? 0u : (z > 0xFFFFFFFFll ? 0xFFFFFFFFu : static_cast<uint32_t>(z));
  s.w = v.w;
  s.s = v.s;
  s.t = v.t;
  for (int k = 0; k < 4; ++k) s.c[k] = v.c[k];
  return s;
}

int64_t screen_area2(const ScreenVert& a, const ScreenVert& b, const ScreenVert& c) {
  return (static_cast<int64_t>(b.x) - a.x) * (static_cast<int64_t>(c.y) - a.y) -
         (static_cast<int64_t>(c.x) - a.x) * (static_cast<int64_t>(b.y) - a.y);
}

}  // namespace htx::render
