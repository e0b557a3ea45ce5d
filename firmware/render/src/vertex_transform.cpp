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
  // F = 48 - P, but no more than mvp.frac + 1 (mat4_mul chooses the entries below 2^29 at
  // mvp.frac) and none beyond 2^30 (an entry of 2^14 or more is above 2^29 at the least frac, 16).
  uint32_t largest = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) {
      const int32_t e = mvp.m[i][j];
      const uint32_t mag = e < 0 ? 0u - static_cast<uint32_t>(e) : static_cast<uint32_t>(e);
      if (mag > largest) largest = mag;
    }
  const int headroom = 30 - (32 - clz32(largest));
  int f = 48 - p;
  if (f > mvp.frac + 1) f = mvp.frac + 1;
  if (f > mvp.frac + headroom) f = mvp.frac + headroom;
  vt.in_shift = p - kFracBits;
  vt.out_shift = 48 - p - f;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) {
      const int64_t e = mvp.m[i][j];
      vt.m[i][j] = f >= mvp.frac ? static_cast<int32_t>(shift_left(e, f - mvp.frac))
                                 : static_cast<int32_t>(round_shift(e, mvp.frac - f));
    }
    // Three truncating products lose up to 3 ulps, 1.5 on average: adding one centres it.
    vt.t[i] = saturate32(int64_t{mvp.m[i][3]} + (vt.out_shift == 0 ? 1 : 0));
  }
  return vt;
}

namespace {

// Whether mvp may take a position below 2^position_bits out of Q16.16, or has saturated an entry:
// Σ|m_ij|·2^position_bits + |t_i| per row, in 32-bit steps (each term checked against the room
// left, so nothing overflows), cheap enough for every mesh. The room keeps 2^20 (16 units) for
// rounding: the entries' own (half an ulp at frac >= 16, times positions below 2^14) and the
// per-vertex products'.
bool clip_may_leave_q16(const Mat4& mvp, int position_bits) {
  const int up = position_bits + kFracBits - mvp.frac;  // -14 .. 14: a linear entry's weight, 2^up
  for (int i = 0; i < 4; ++i) {
    uint32_t room = (1u << 31) - (1u << 20);
    for (int j = 0; j < 4; ++j) {
      const int32_t e = mvp.m[i][j];
      if (e == INT32_MAX || e == INT32_MIN) return true;
      uint32_t mag = e < 0 ? 0u - static_cast<uint32_t>(e) : static_cast<uint32_t>(e);
      if (j < 3 && up >= 0) {
        if (mag > (room >> up)) return true;
        mag <<= up;
      } else if (j < 3) {
        mag >>= -up;
      }
      if (mag >= room) return true;
      room -= mag;
    }
  }
  return false;
}

}  // namespace

Mat4 mesh_mvp(const Mat4& view_proj, const Mat4& model, int position_bits, int* down) {
  Mat4 mvp = mat4_mul(view_proj, model);
  int d = 0;
  // Rare (a large scene seen from far away), so simply tried again a power of two further down.
  while (d < kMaxMeshScaleDown && clip_may_leave_q16(mvp, position_bits)) {
    ++d;
    mvp = mat4_mul(mat4_scaled_down(view_proj, d), model);
  }
  if (down) *down = d;
  return mvp;
}

VertexTransform make_mesh_transform(const Mat4& view_proj, const Mat4& model, int position_bits) {
  return make_vertex_transform(mesh_mvp(view_proj, model, position_bits, nullptr), position_bits);
}

}  // namespace htx::render
