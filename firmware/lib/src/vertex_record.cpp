#include "htx/fw/vertex_record.h"

#include "htx/fw/fixed_point.h"

namespace htx::fw {

namespace {

bool finite(double x) { return x == x && x < 1.7e308 && x > -1.7e308; }

uint32_t channel8(double c) { return static_cast<uint32_t>(round_nearest(clamp_double(c, 0.0, 1.0) * 255.0)); }

// Midpoint of the range of three values, rounded to an integer texel.
int64_t offset_of(double a, double b, double c) {
  double lo = a, hi = a;
  if (b < lo) lo = b;
  if (c < lo) lo = c;
  if (b > hi) hi = b;
  if (c > hi) hi = c;
  return round_nearest(0.5 * lo + 0.5 * hi);
}

}  // namespace

EncodeStatus encode_triangle(const RecordFormat& f, const VertexIn in[3], TriangleRecord* out) {
  if (f.xy_int_bits < 2 || f.xy_int_bits > 22 || f.z_bits < 8 || f.z_bits > 24 || f.q_bits < 8 ||
      f.q_bits > 32 || f.uv_int_bits < 2 || f.uv_int_bits > 24)
    return kEncodeBadFormat;
  for (int i = 0; i < 3; ++i) {
    const VertexIn& v = in[i];
    if (!finite(v.x) || !finite(v.y) || !finite(v.z) || !finite(v.w) || !finite(v.u) || !finite(v.v))
      return kEncodeNotFinite;
    if (!(v.w > 0)) return kEncodeBadW;
  }
  const double xy_limit = scale_by_pow2(1.0, f.xy_int_bits - 1);
  const int64_t z_max = (INT64_C(1) << f.z_bits) - 1;
  // The largest q sets the shared exponent.
  double qmax = 0;
  for (int i = 0; i < 3; ++i) {
    const double q = 1.0 / in[i].w;
    if (q > qmax) qmax = q;
  }
  if (!finite(qmax)) return kEncodeBadW;
  const int q_exp = normalising_exponent(qmax);
  const int64_t q_top = (INT64_C(1) << f.q_bits) - 1;
  const int64_t uv_limit = INT64_C(1) << (f.uv_int_bits - 1);
  const int64_t ou = offset_of(in[0].u, in[1].u, in[2].u);
  const int64_t ov = offset_of(in[0].v, in[1].v, in[2].v);
  if (ou >= (INT64_C(1) << 30) || ou <= -(INT64_C(1) << 30) || ov >= (INT64_C(1) << 30) ||
      ov <= -(INT64_C(1) << 30))
    return kEncodeUvRange;
  out->u_offset = static_cast<int32_t>(ou);
  out->v_offset = static_cast<int32_t>(ov);
  out->q_exp = q_exp;
  for (int i = 0; i < 3; ++i) {
    const VertexIn& v = in[i];
    VertexRecord& r = out->v[i];
    if (!(v.x > -xy_limit && v.x < xy_limit && v.y > -xy_limit && v.y < xy_limit)) return kEncodeXyRange;
    // Range is checked again after rounding: a value just below the limit rounds up onto it.
    const int64_t xy_units = INT64_C(1) << (f.xy_int_bits - 1 + kSubpixelBits);
    const int64_t rx = round_nearest(v.x * 256.0);
    const int64_t ry = round_nearest(v.y * 256.0);
    if (rx < -xy_units || rx >= xy_units || ry < -xy_units || ry >= xy_units) return kEncodeXyRange;
    r.x = static_cast<int32_t>(rx);
    r.y = static_cast<int32_t>(ry);
    r.z = static_cast<uint32_t>(round_nearest(clamp_double(v.z, 0.0, 1.0) * static_cast<double>(z_max)));
    int64_t q = round_nearest(scale_by_pow2(1.0 / v.w, q_exp + f.q_bits));
    // A q below one unit (depth ratio beyond 2^q_bits inside one triangle) is raised to one unit.
    if (q < 1) q = 1;
    if (q > q_top) q = q_top;
    r.q = static_cast<uint32_t>(q);
    const double ul = v.u - static_cast<double>(ou);
    const double vl = v.v - static_cast<double>(ov);
    const double lim = static_cast<double>(uv_limit);
    if (!(ul > -lim && ul < lim && vl > -lim && vl < lim)) return kEncodeUvRange;
    // The products use the quantised q, so uq / q reproduces u at the vertex to 1/(2q) texel.
    r.uq = round_nearest(ul * static_cast<double>(q));
    r.vq = round_nearest(vl * static_cast<double>(q));
    r.rgba = channel8(v.r) | (channel8(v.g) << 8) | (channel8(v.b) << 16) | (channel8(v.a) << 24);
  }
  return kEncodeOk;
}

void pack_triangle(const TriangleRecord& tri, uint32_t words[kTriangleWords]) {
  words[0] = static_cast<uint32_t>(tri.u_offset);
  words[1] = static_cast<uint32_t>(tri.v_offset);
  words[2] = static_cast<uint32_t>(tri.q_exp);
  for (int i = 0; i < 3; ++i) {
    const VertexRecord& r = tri.v[i];
    uint32_t* w = words + 3 + i * kWordsPerVertex;
    w[0] = static_cast<uint32_t>(r.x);
    w[1] = static_cast<uint32_t>(r.y);
    w[2] = r.z;
    w[3] = r.q;
    w[4] = static_cast<uint32_t>(static_cast<uint64_t>(r.uq));
    w[5] = static_cast<uint32_t>(static_cast<uint64_t>(r.uq) >> 32);
    w[6] = static_cast<uint32_t>(static_cast<uint64_t>(r.vq));
    w[7] = static_cast<uint32_t>(static_cast<uint64_t>(r.vq) >> 32);
    w[8] = r.rgba;
  }
}

void unpack_triangle(const uint32_t words[kTriangleWords], TriangleRecord* tri) {
  tri->u_offset = static_cast<int32_t>(words[0]);
  tri->v_offset = static_cast<int32_t>(words[1]);
  tri->q_exp = static_cast<int32_t>(words[2]);
  for (int i = 0; i < 3; ++i) {
    VertexRecord& r = tri->v[i];
    const uint32_t* w = words + 3 + i * kWordsPerVertex;
    r.x = static_cast<int32_t>(w[0]);
    r.y = static_cast<int32_t>(w[1]);
    r.z = w[2];
    r.q = w[3];
    r.uq = static_cast<int64_t>(static_cast<uint64_t>(w[4]) | (static_cast<uint64_t>(w[5]) << 32));
    r.vq = static_cast<int64_t>(static_cast<uint64_t>(w[6]) | (static_cast<uint64_t>(w[7]) << 32));
    r.rgba = w[8];
  }
}

}  // namespace htx::fw
