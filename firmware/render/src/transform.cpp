#include "htx/render/transform.h"

#include "htx/render/fixed.h"

namespace htx::render {

namespace {

int column_frac(const Mat4& a, int col) { return col < 3 ? a.frac : kFracBits; }

// Entry (i, j) of a * b with `frac` fraction bits, 64-bit: each product rounded to `frac` first.
int64_t product_entry(const Mat4& a, const Mat4& b, int i, int j, int frac) {
  int64_t s = 0;
  for (int k = 0; k < 4; ++k) {
    const int64_t p = static_cast<int64_t>(a.m[i][k]) * b.m[k][j];
    s += round_shift(p, column_frac(a, k) + column_frac(b, j) - frac);
  }
  return s;
}

int bit_length(uint64_t v) {
  int n = 0;
  while (v) {
    ++n;
    v >>= 1;
  }
  return n;
}

}  // namespace

Mat4 mat4_identity() {
  Mat4 r{};
  r.frac = kMatMaxFrac;
  for (int i = 0; i < 3; ++i) r.m[i][i] = int32_t{1} << kMatMaxFrac;
  r.m[3][3] = kOne;
  return r;
}

Mat4 mat4_mul(const Mat4& a, const Mat4& b) {
  // First the linear part in Q16.16 to find its magnitude, then every entry at the chosen precision.
  uint64_t largest = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) {
      const int64_t e = product_entry(a, b, i, j, kFracBits);
      const uint64_t mag = static_cast<uint64_t>(e < 0 ? -e : e);
      if (mag > largest) largest = mag;
    }
  int frac = 45 - bit_length(largest);  // largest * 2^(frac - 16) < 2^29, margin for rounding
  if (frac > kMatMaxFrac) frac = kMatMaxFrac;
  if (frac < kMatMinFrac) frac = kMatMinFrac;
  Mat4 r{};
  r.frac = frac;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = saturate32(product_entry(a, b, i, j, j < 3 ? frac : kFracBits));
  return r;
}

Vec4 transform_point(const Mat4& m, int32_t x, int32_t y, int32_t z) {
  int32_t out[4];
  const int f = m.frac;
  for (int i = 0; i < 4; ++i) {
    const int64_t s = static_cast<int64_t>(m.m[i][0]) * x + static_cast<int64_t>(m.m[i][1]) * y +
                      static_cast<int64_t>(m.m[i][2]) * z + (static_cast<int64_t>(m.m[i][3]) << f);
    out[i] = saturate32(round_shift(s, f));
  }
  return {out[0], out[1], out[2], out[3]};
}

}  // namespace htx::render
