#include "htx/render/encode.h"

#include "htx/render/fixed.h"

namespace htx::render {

namespace {

// round(c / 2^16) clamped to 0..255, in 32 bits: floor((c + 2^15) / 2^16) is c's integer part
// plus its first fraction bit (no 64-bit sum on the CPU, and no overflow near INT32_MAX).
uint32_t channel8(int32_t c) {
  static_assert(kFracBits == 16, "the rounding bit below is fraction bit 15");
  const int32_t r = (c >> 16) + ((c >> 15) & 1);
  return r < 0 ? 0u : (r > 255 ? 255u : static_cast<uint32_t>(r));
}

// Midpoint of the range of three Q16.16 values, rounded to an integer (floor(x + 1/2)).
int64_t offset_of(const int64_t a[3]) {
  int64_t lo = a[0], hi = a[0];
  for (int i = 1; i < 3; ++i) {
    if (a[i] < lo) lo = a[i];
    if (a[i] > hi) hi = a[i];
  }
  return (lo + hi + (int64_t{1} << kFracBits)) >> (kFracBits + 1);
}

}  // namespace

fw::EncodeStatus encode_triangle_fx(const fw::RecordFormat& f, const ScreenVert* const v[3], TexSize tex,
                                    fw::TriangleRecord* out) {
  if (f.xy_int_bits < 2 || f.xy_int_bits > 22 || f.z_bits < 8 || f.z_bits > 24 || f.q_bits < 8 ||
      f.q_bits > 32 || f.uv_int_bits < 2 || f.uv_int_bits > 24 || tex.log2_width > 15 || tex.log2_height > 15)
    return fw::kEncodeBadFormat;
  const int64_t xy_limit = int64_t{1} << (f.xy_int_bits - 1 + fw::kSubpixelBits);
  for (int i = 0; i < 3; ++i) {
    if (v[i]->w <= 0 || v[i]->inv_w.mant == 0) return fw::kEncodeBadW;
    if (!(v[i]->x > -xy_limit && v[i]->x < xy_limit && v[i]->y > -xy_limit && v[i]->y < xy_limit))
      return fw::kEncodeXyRange;
  }
  // The shared exponent: the largest q = 1/w has the largest lz (then the largest mantissa).
  // 1/w = 2^16 / w_raw = (mant / 2^32) * 2^(lz - 15), so q_exp = 15 - lz of that vertex.
  int top = 0;
  for (int i = 1; i < 3; ++i)
    if (v[i]->inv_w.lz > v[top]->inv_w.lz ||
        (v[i]->inv_w.lz == v[top]->inv_w.lz && v[i]->inv_w.mant > v[top]->inv_w.mant))
      top = i;
  const int lz_max = v[top]->inv_w.lz;
  out->q_exp = 15 - lz_max;
  const int64_t q_top = (int64_t{1} << f.q_bits) - 1;

  // u, v in level-0 texels, Q16.16 (64 bits: up to 2^15 normalised units times 2^15 texels).
  int64_t us[3], vs[3];
  for (int i = 0; i < 3; ++i) {
    us[i] = shift_left(static_cast<int64_t>(v[i]->attr->s), tex.log2_width);
    vs[i] = shift_left(static_cast<int64_t>(v[i]->attr->t), tex.log2_height);
  }
  const int64_t ou = offset_of(us), ov = offset_of(vs);
  const int64_t off_limit = int64_t{1} << 30;
  if (ou >= off_limit || ou <= -off_limit || ov >= off_limit || ov <= -off_limit) return fw::kEncodeUvRange;
  out->u_offset = static_cast<int32_t>(ou);
  out->v_offset = static_cast<int32_t>(ov);
  // u - u_offset must fit the record (uv_int_bits) and the 32-bit product operand (16 bits).
  const int uv_bits = f.uv_int_bits < 16 ? f.uv_int_bits : 16;
  const int64_t uv_limit = int64_t{1} << (uv_bits - 1 + kFracBits);
  const uint64_t z_max = (uint64_t{1} << f.z_bits) - 1;

  for (int i = 0; i < 3; ++i) {
    const ScreenVert& s = *v[i];
    fw::VertexRecord& r = out->v[i];
    r.x = s.x;
    r.y = s.y;
    r.z = static_cast<uint32_t>((static_cast<uint64_t>(s.z) * z_max + 0x80000000ull) >> 32);
    // q = round(mant * 2^(q_bits - 32 - (lz_max - lz))); the shift is at least 0 (q_bits <= 32).
    const int shift = 32 - f.q_bits + (lz_max - s.inv_w.lz);
    int64_t q = round_shift_u32(s.inv_w.mant, shift);
    if (q < 1) q = 1;  // a depth ratio beyond 2^q_bits inside one triangle: raised to one unit
    if (q > q_top) q = q_top;
    r.q = static_cast<uint32_t>(q);
    const int64_t ul = us[i] - shift_left(ou, kFracBits);
    const int64_t vl = vs[i] - shift_left(ov, kFracBits);
    if (!(ul > -uv_limit && ul < uv_limit && vl > -uv_limit && vl < uv_limit)) return fw::kEncodeUvRange;
    // The products use the quantised q, so uq / q reproduces u at the vertex to 1/(2q) texel.
    r.uq = round_shift(static_cast<int64_t>(static_cast<int32_t>(ul)) * q, kFracBits);
    r.vq = round_shift(static_cast<int64_t>(static_cast<int32_t>(vl)) * q, kFracBits);
    const int32_t* c = s.attr->c;
    r.rgba = channel8(c[0]) | (channel8(c[1]) << 8) | (channel8(c[2]) << 16) | (channel8(c[3]) << 24);
  }
  return fw::kEncodeOk;
}

}  // namespace htx::render
