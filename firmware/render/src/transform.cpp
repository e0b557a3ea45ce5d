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

Mat4 mat4_scaled_down(const Mat4& m, int down) {
  Mat4 r = m;
  if (down <= 0) return r;
  // The linear part keeps its integers and takes `down` more fraction bits, as far as the format
  // goes; the rest, and the Q16.16 translation, are rounded off.
  const int more = m.frac + down > kMatMaxFrac ? kMatMaxFrac - m.frac : down;
  r.frac = m.frac + more;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j)
      if (down > more) r.m[i][j] = static_cast<int32_t>(round_shift(m.m[i][j], down - more));
    r.m[i][3] = static_cast<int32_t>(round_shift(m.m[i][3], down));
  }
  return r;
}

Vec4 transform_point(const Mat4& m, int32_t x, int32_t y, int32_t z) {
  int32_t out[4];
  const int f = m.frac;
  for (int i = 0; i < 4; ++i) {
    const int64_t s = static_cast<int64_t>(m.m[i][0]) * x + static_cast<int64_t>(m.m[i][1]) * y +
                      static_cast<int64_t>(m.m[i][2]) * z + shift_left(static_cast<int64_t>(m.m[i][3]), f);
    out[i] = saturate32(round_shift(s, f));
  }
  return {out[0], out[1], out[2], out[3]};
}

namespace {

constexpr int kTrigFrac = 30;
constexpr int64_t kTrigOne = int64_t{1} << kTrigFrac;

int64_t mul_q30(int64_t a, int64_t b) { return round_shift(a * b, kTrigFrac); }

// 2^30 / n!, rounded.
constexpr int64_t kInvFact3 = 178956971, kInvFact5 = 8947849, kInvFact7 = 213044, kInvFact9 = 2959;
constexpr int64_t kInvFact2 = 536870912, kInvFact4 = 44739243, kInvFact6 = 1491308, kInvFact8 = 26631,
                  kInvFact10 = 296;

// sin and cos of x radians (Q30), 0 <= x <= pi/4, by Horner's rule.
void sin_cos_octant(int64_t x, int64_t* s, int64_t* c) {
  const int64_t x2 = mul_q30(x, x);
  int64_t p = kInvFact9;
  p = kInvFact7 - mul_q30(x2, p);
  p = kInvFact5 - mul_q30(x2, p);
  p = kInvFact3 - mul_q30(x2, p);
  p = kTrigOne - mul_q30(x2, p);
  *s = mul_q30(x, p);
  int64_t q = kInvFact10;
  q = kInvFact8 - mul_q30(x2, q);
  q = kInvFact6 - mul_q30(x2, q);
  q = kInvFact4 - mul_q30(x2, q);
  q = kInvFact2 - mul_q30(x2, q);
  *c = kTrigOne - mul_q30(x2, q);
}

}  // namespace

void sin_cos_turns(uint32_t turn_q16, int32_t* sine, int32_t* cosine) {
  constexpr uint32_t kQuarter = 1u << 14, kEighth = 1u << 13;
  constexpr int64_t kTwoPiQ30 = 6746518852;  // 2 pi 2^30, rounded
  const uint32_t t = turn_q16 & 0xFFFFu;
  const uint32_t quadrant = t >> 14;
  const uint32_t u = t & (kQuarter - 1);  // 0 .. a quarter turn
  // Within the quadrant, the nearer end of it keeps the argument below pi/4.
  const bool upper = u > kEighth;
  const int64_t x = round_shift(static_cast<int64_t>(upper ? kQuarter - u : u) * kTwoPiQ30, 16);
  int64_t s0 = 0, c0 = 0;
  sin_cos_octant(x, &s0, &c0);
  if (upper) {
    const int64_t swap = s0;
    s0 = c0;
    c0 = swap;
  }
  int64_t s = s0, c = c0;
  switch (quadrant) {
    case 1: s = c0; c = -s0; break;
    case 2: s = -s0; c = -c0; break;
    case 3: s = -c0; c = s0; break;
    default: break;
  }
  // |s|, |c| <= 2^30: on [0, pi/4] the sine polynomial stays below 0.71 and the cosine is 1
  // minus a product that is not negative.
  *sine = static_cast<int32_t>(s);
  *cosine = static_cast<int32_t>(c);
}

Mat4 mat4_rotation_y(uint32_t turn_q16) {
  int32_t s = 0, c = 0;
  sin_cos_turns(turn_q16, &s, &c);
  Mat4 r = mat4_identity();  // frac 30
  r.m[0][0] = c;
  r.m[0][2] = s;
  r.m[2][0] = -s;
  r.m[2][2] = c;
  return r;
}

Mat4 mat4_rotation_y_about(uint32_t turn_q16, int32_t cx, int32_t cz) {
  // T(c) R T(-c): the linear part is R's, the translation c - R c.
  Mat4 r = mat4_rotation_y(turn_q16);
  const int64_t rx = round_shift(static_cast<int64_t>(r.m[0][0]) * cx + static_cast<int64_t>(r.m[0][2]) * cz, r.frac);
  const int64_t rz = round_shift(static_cast<int64_t>(r.m[2][0]) * cx + static_cast<int64_t>(r.m[2][2]) * cz, r.frac);
  r.m[0][3] = saturate32(cx - rx);
  r.m[2][3] = saturate32(cz - rz);
  return r;
}

}  // namespace htx::render
