// Vertex-record encoder (firmware/lib): rounding, q normalisation, texel offsets, range errors,
// FIFO packing.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "htx/fw/fixed_point.h"
#include "htx/fw/vertex_record.h"

namespace htx::fw {
namespace {

TEST(FixedPoint, RoundNearestTiesUp) {
  EXPECT_EQ(round_nearest(1.5), 2);
  EXPECT_EQ(round_nearest(-1.5), -1);
  EXPECT_EQ(round_nearest(-1.6), -2);
  EXPECT_EQ(round_nearest(2.4999), 2);
  EXPECT_EQ(round_nearest(-0.5), 0);
  EXPECT_EQ(round_nearest(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(round_nearest(1e300), INT64_C(4611686018427387904));
  // Exactly floor(x + 0.5), without rounding x + 0.5 first: just below a half, and past 2^52
  // (where x + 0.5 rounds to the next even double).
  EXPECT_EQ(round_nearest(0.49999999999999994), 0);
  EXPECT_EQ(round_nearest(-0.50000000000000011), -1);
  EXPECT_EQ(round_nearest(4503599627370497.0), INT64_C(4503599627370497));
  EXPECT_EQ(round_nearest(-4503599627370497.0), -INT64_C(4503599627370497));
  EXPECT_EQ(round_nearest(4503599627370495.5), INT64_C(4503599627370496));
  EXPECT_EQ(normalising_exponent(1.0), -1);
  EXPECT_EQ(normalising_exponent(0.5), 0);
  EXPECT_EQ(normalising_exponent(0.001), 9);
  EXPECT_EQ(scale_by_pow2(3.0, -2), 0.75);
}

void set(VertexIn& v, double x, double y, double w, double u, double vv) {
  v.x = x, v.y = y, v.w = w, v.u = u, v.v = vv, v.z = 0.25;
}

TEST(VertexRecord, QuantisesAsDocumented) {
  const RecordFormat f{16, 24, 32, 16};
  VertexIn in[3];
  set(in[0], 10.5 / 256 + 3, -1.5 / 256, 1.0, 1000.25, -7.0);
  set(in[1], 20, 5, 2.0, 1010.75, -3.0);
  set(in[2], 7, 9, 4.0, 1004.0, -5.0);
  in[0].r = 1.0, in[0].g = 0.5, in[0].b = 0.0, in[0].a = 2.0;
  TriangleRecord r;
  ASSERT_EQ(encode_triangle(f, in, &r), kEncodeOk);
  EXPECT_EQ(r.v[0].x, 3 * 256 + 11);  // 778.5 rounds up
  EXPECT_EQ(r.v[0].y, -1);            // -1.5 rounds up to -1
  EXPECT_EQ(r.v[1].x, 20 * 256);
  EXPECT_EQ(r.v[0].z, 4194304u);      // 0.25 * (2^24 - 1) = 4194303.75
  // q = 1, 1/2, 1/4: the largest lands in [2^31, 2^32).
  EXPECT_EQ(r.q_exp, -1);
  EXPECT_EQ(r.v[0].q, 1u << 31);
  EXPECT_EQ(r.v[1].q, 1u << 30);
  EXPECT_EQ(r.v[2].q, 1u << 29);
  // Offsets: midpoints of [1000.25, 1010.75] -> 1005.5 -> 1006, [-7, -3] -> -5.
  EXPECT_EQ(r.u_offset, 1006);
  EXPECT_EQ(r.v_offset, -5);
  EXPECT_EQ(r.v[0].uq, static_cast<int64_t>(-5.75 * 2147483648.0));
  EXPECT_EQ(r.v[1].uq, static_cast<int64_t>(4.75 * 1073741824.0));
  EXPECT_EQ(r.v[2].vq, 0);
  EXPECT_EQ(r.v[0].rgba, 0xFF0080FFu);  // a clamped to 1, g = round(127.5) = 128
}

TEST(VertexRecord, LargeTexelCoordinatesKeepFullPrecision) {
  const RecordFormat f{16, 24, 32, 16};
  VertexIn in[3];
  set(in[0], 0, 0, 1.0, 16384.0 + 1.0 / 1024, -16000.5);
  set(in[1], 100, 0, 1000.0, 16384.0 + 200.0, -16000.5 + 100);
  set(in[2], 0, 100, 10.0, 16384.0 - 300.0, -16000.5 - 70);
  TriangleRecord r;
  ASSERT_EQ(encode_triangle(f, in, &r), kEncodeOk);
  for (int i = 0; i < 3; ++i) {
    const double u = r.u_offset + static_cast<double>(r.v[i].uq) / r.v[i].q;
    const double v = r.v_offset + static_cast<double>(r.v[i].vq) / r.v[i].q;
    EXPECT_NEAR(u, in[i].u, 1e-5) << i;
    EXPECT_NEAR(v, in[i].v, 1e-5) << i;
  }
}

TEST(VertexRecord, RejectsWhatItCannotRepresent) {
  const RecordFormat f{14, 16, 20, 13};
  VertexIn in[3];
  TriangleRecord r;
  set(in[0], 0, 0, 1, 0, 0), set(in[1], 10, 0, 1, 0, 0), set(in[2], 0, 10, 1, 0, 0);
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeOk);
  in[1].x = 8192;  // +-2^13 pixels with 14 integer bits
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeXyRange);
  in[1].x = 8191.9;
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeOk);
  in[1].x = 8191.999;  // below the limit, but rounds onto 2^13 pixels: out of range after rounding
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeXyRange);
  in[1].x = -8192.001;  // rounds onto -2^13 pixels, the most negative representable value
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeXyRange);
  in[1].x = -8191.999;
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeOk);
  in[1].x = 8191.9;
  in[1].u = 8192;  // spans 8192 texels: 4096 each side of the midpoint is out of range
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeUvRange);
  in[1].u = 8190;
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeOk);
  in[2].w = 0;
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeBadW);
  in[2].w = 1;
  in[0].y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(encode_triangle(f, in, &r), kEncodeNotFinite);
  const RecordFormat bad{14, 16, 40, 13};
  in[0].y = 0;
  EXPECT_EQ(encode_triangle(bad, in, &r), kEncodeBadFormat);
}

TEST(VertexRecord, PackUnpackRoundTrips) {
  TriangleRecord r;
  r.u_offset = -123456;
  r.v_offset = 789;
  r.q_exp = -7;
  for (int i = 0; i < 3; ++i) {
    r.v[i].x = -1000 * (i + 1);
    r.v[i].y = 77 * i;
    r.v[i].z = 0xABCDEFu + i;
    r.v[i].q = 0xF0000000u >> i;
    r.v[i].uq = -(INT64_C(1) << 46) + i;
    r.v[i].vq = (INT64_C(1) << 45) - 3 * i;
    r.v[i].rgba = 0x11223344u * (i + 1);
  }
  uint32_t words[kTriangleWords];
  pack_triangle(r, words);
  TriangleRecord back;
  unpack_triangle(words, &back);
  EXPECT_EQ(back.u_offset, r.u_offset);
  EXPECT_EQ(back.v_offset, r.v_offset);
  EXPECT_EQ(back.q_exp, r.q_exp);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(back.v[i].x, r.v[i].x);
    EXPECT_EQ(back.v[i].y, r.v[i].y);
    EXPECT_EQ(back.v[i].z, r.v[i].z);
    EXPECT_EQ(back.v[i].q, r.v[i].q);
    EXPECT_EQ(back.v[i].uq, r.v[i].uq);
    EXPECT_EQ(back.v[i].vq, r.v[i].vq);
    EXPECT_EQ(back.v[i].rgba, r.v[i].rgba);
  }
}

}  // namespace
}  // namespace htx::fw
