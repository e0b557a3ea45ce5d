#include "htx/render/vertex_transform.h"

#include "htx/render/fixed.h"

namespace htx::render {

int position_int_bits(const int32_t* xyz, uint32_t count, uint32_t stride_words) {
  uint32_t any = 0;
  for (uint32_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) {
      const int32_t c = xyz[i * stride_words + static_cast<uint32_t>(k)];
      any |= static_cast<uint32_t>(c < 0 ? -(c + 1) : c);  // |c| rounded down, no overflow at INT32_MIN
    }
  int bits = 32 - clz32(any);  // bits of the largest magnitude in Q16.16
  bits -= kFracBits;
  return bits < 0 ? 0 : (bits > 15 ? 15 : bits);
}

VertexTransform make_vertex_transform(const Mat4& mvp, int position_bits) {
  VertexTransform vt{};
  // P: one bit of headroom above the largest coordinate, at least Q16.16 (coordinates of 2^14 and
  // more have none: the documented limit of the format).
  int p = 30 - position_bits;
  if (p < kFracBits) p = kFracBits;
  if (p > 30) p = 30;
  // F = 48 - P, but no more than mvp.frac + 1 (the entries were chosen below 2^29 at mvp.frac).
  int f = 48 - p;
  if (f > mvp.frac + 1) f = mvp.frac + 1;
  vt.in_shift = p - kFracBits;
  vt.out_shift = 48 - p - f;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) {
      const int64_t e = mvp.m[i][j];
      vt.m[i][j] = f >= mvp.frac ? static_cast<int32_t>(shift_left(e, f - mvp.frac))
                                 : static_cast<int32_t>(round_shift(e, mvp.frac - f));
    }
    // Three truncating products lose up to 3 ulps, 1.5 on average: adding one centres it.
    vt.t[i] = mvp.m[i][3] + (vt.out_shift == 0 ? 1 : 0);
  }
  return vt;
}

}  // namespace htx::render
