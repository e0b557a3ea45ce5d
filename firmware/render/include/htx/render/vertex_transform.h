// The per-vertex transform of one mesh in the form the soft CPU evaluates cheaply: twelve 32x32
// high-word products (mulh) and four additions per vertex, no 64-bit carries. Positions are
// pre-shifted to P fraction bits (as many as the mesh's largest coordinate allows) and the linear
// part of the matrix is held with F = 48 - P fraction bits, so each high word is already Q16.16
// (docs/firmware.md, "Number formats").
#pragma once

#include <stdint.h>

#include "htx/render/fixed.h"
#include "htx/render/transform.h"

namespace htx::render {

struct VertexTransform {
  int32_t m[4][3];    // linear part, F fraction bits
  int32_t t[4];       // translation (and rounding bias), Q16.16
  int32_t in_shift;   // positions: Q16.16 << in_shift = P fraction bits
  int32_t out_shift;  // extra left shift of the sums when F + P < 48 (0 for sane scenes)
};

// Integer bits (0..15, sign excluded) the largest |coordinate| of the positions needs.
int position_int_bits(const int32_t* xyz, uint32_t count, uint32_t stride_words);

// For mvp's entries below 2^30 and its clip coordinates inside Q16.16 (make_mesh_transform sees
// to both): otherwise the sums wrap.
VertexTransform make_vertex_transform(const Mat4& mvp, int position_bits);

// view_proj * model for a mesh whose positions are below 2^position_bits, scaled down by 2^down
// (0 for any sane scene) when its clip coordinates could otherwise reach 2^15 or an entry
// saturated (a large scene seen from far away): the projected points are the same, the clip
// coordinates lose low bits. By kMaxMeshScaleDown every entry of view_proj has been rounded to 0,
// so the loop always ends with coordinates that fit (a crafted matrix needed more than 31).
// `down` may be null.
inline constexpr int kMaxMeshScaleDown = 62;
Mat4 mesh_mvp(const Mat4& view_proj, const Mat4& model, int position_bits, int* down);

// The per-vertex form of mesh_mvp's matrix.
VertexTransform make_mesh_transform(const Mat4& view_proj, const Mat4& model, int position_bits);

// Row i of clip = M * (x, y, z, 1) for positions already shifted by in_shift. Each of the three
// products truncates (< 1 ulp); the bias in t centres the sum's error in [-2, 1] ulps.
inline int32_t apply_row(const VertexTransform& vt, int i, int32_t px, int32_t py, int32_t pz) {
  const int32_t s = static_cast<int32_t>((static_cast<int64_t>(vt.m[i][0]) * px) >> 32) +
                    static_cast<int32_t>((static_cast<int64_t>(vt.m[i][1]) * py) >> 32) +
                    static_cast<int32_t>((static_cast<int64_t>(vt.m[i][2]) * pz) >> 32);
  return shift_left(s, vt.out_shift) + vt.t[i];
}

// clip = M * (x, y, z, 1), Q16.16 in and out.
inline Vec4 apply(const VertexTransform& vt, int32_t x, int32_t y, int32_t z) {
  const int32_t px = shift_left(x, vt.in_shift), py = shift_left(y, vt.in_shift), pz = shift_left(z, vt.in_shift);
  return {apply_row(vt, 0, px, py, pz), apply_row(vt, 1, px, py, pz), apply_row(vt, 2, px, py, pz),
          apply_row(vt, 3, px, py, pz)};
}

}  // namespace htx::render
