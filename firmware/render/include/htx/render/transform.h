// 4x4 transforms: column-vector convention (p' = M p), row-major m[row][col], like the host's
// htx::Mat4. Points are Q16.16. Matrix entries of columns 0..2 (the linear part, including the w
// row's) have `frac` fraction bits, chosen per matrix in 16..30 so the largest is below 2^30; column
// 3 (translation) is Q16.16. A projection's depth row needs the extra bits: with far/near = 4000,
// Q16.16 would move the far plane by percents. Each output coordinate is a sum of 64-bit products
// rounded once (docs/firmware.md, "Number formats").
#pragma once

#include <stdint.h>

namespace htx::render {

inline constexpr int kMatMinFrac = 16;
inline constexpr int kMatMaxFrac = 30;

struct Mat4 {
  int32_t m[4][4];
  int32_t frac;  // fraction bits of columns 0..2, kMatMinFrac..kMatMaxFrac
};

struct Vec4 {
  int32_t x, y, z, w;
};

Mat4 mat4_identity();
// a * b with the most fraction bits its largest linear entry allows (every entry rounded once,
// saturating when an entry leaves the format: linear part beyond 2^14, translation beyond 2^15).
Mat4 mat4_mul(const Mat4& a, const Mat4& b);
// m * 2^-down (down >= 0): a homogeneous transform scaled by a positive factor projects every
// point to the same place, so the geometry scales a mesh's down when its clip coordinates would
// leave Q16.16 (make_mesh_transform).
Mat4 mat4_scaled_down(const Mat4& m, int down);
// M * (x, y, z, 1) for a point in Q16.16.
Vec4 transform_point(const Mat4& m, int32_t x, int32_t y, int32_t z);

// sin and cos of an angle given in turns, Q16 (65,536 = a whole turn), as Q2.30 (octant reduction
// and Taylor polynomials to x^9 and x^10 on [0, pi/4]: within 3 units of the last place).
void sin_cos_turns(uint32_t turn_q16, int32_t* sine, int32_t* cosine);
// Rotation about the y axis by turn_q16 (x towards -z for small angles: right-handed, seen from
// +y anticlockwise), frac 30.
Mat4 mat4_rotation_y(uint32_t turn_q16);
// The same rotation about the vertical line through (cx, *, cz), Q16.16: points on it stay put
// (the translation saturates where it leaves Q16.16).
Mat4 mat4_rotation_y_about(uint32_t turn_q16, int32_t cx, int32_t cz);

}  // namespace htx::render
