// The vertex-record format of the raster unit and its encoder (docs/model.md, "Vertex record").
// The firmware encodes triangles with exactly this code, and the host model consumes the same
// records, so quantisation is bit-identical on both sides. Freestanding C++17.
//
// A triangle is a header (state, texel offsets, q exponent) and three vertex records:
//   x, y   signed, 8 fractional (subpixel) bits, xy_int_bits integer bits including the sign
//   z      unsigned z_bits, z in [0, 1] scaled by 2^z_bits - 1
//   q      unsigned q_bits: 1/w scaled per triangle so that the largest vertex q lies in
//          [2^(q_bits-1), 2^q_bits); the shared exponent q_exp records the scale (it cancels in u = uq/q)
//   uq, vq signed: (u - u_offset) * q and (v - v_offset) * q as integers, where u_offset and
//          v_offset are per-triangle integer texel offsets (the midpoint of the triangle's u and v
//          ranges), so |u - u_offset| < 2^(uv_int_bits - 1) texels keeps full precision at any |u|
//   rgba   8 bits per channel, c * 255
// Every value is rounded to nearest, ties toward +infinity (round_nearest).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace htx::fw {

// Field widths of one configuration (a subset of the model's ModelConfig).
struct RecordFormat {
  uint8_t xy_int_bits = 16;  // integer bits of x and y including the sign (8 fractional bits follow)
  uint8_t z_bits = 24;       // 8..24 (the encoders refuse others); the GPU builds use 16 and 24
  uint8_t q_bits = 32;       // 8..32
  uint8_t uv_int_bits = 16;  // integer bits of u - u_offset including the sign, 2..24
};

inline constexpr int kSubpixelBits = 8;

// A vertex as the geometry stage delivers it (screen pixels, depth 0..1, clip w, level-0 texels).
struct VertexIn {
  double x = 0, y = 0, z = 0, w = 1, u = 0, v = 0;
  double r = 1, g = 1, b = 1, a = 1;
};

struct VertexRecord {
  int32_t x = 0, y = 0;  // 1/256 pixel
  uint32_t z = 0;
  uint32_t q = 0;
  int64_t uq = 0, vq = 0;
  uint32_t rgba = 0;  // r in bits 7:0, g 15:8, b 23:16, a 31:24
};

struct TriangleRecord {
  int32_t u_offset = 0, v_offset = 0;  // integer texels added back after the division
  int32_t q_exp = 0;                   // q_record = q * 2^(q_exp + q_bits)
  VertexRecord v[3];
};

enum EncodeStatus : int {
  kEncodeOk = 0,
  kEncodeNotFinite = 1,  // a coordinate is NaN or infinite
  kEncodeBadW = 2,       // w <= 0 (the geometry stage clips before the divide)
  kEncodeXyRange = 3,    // x or y outside +-2^(xy_int_bits - 1) pixels
  kEncodeUvRange = 4,    // the triangle spans 2^(uv_int_bits - 1) texels or more, or |offset| >= 2^30
  kEncodeBadFormat = 5,  // a width outside its documented range
};

// Quantises one triangle. On an error nothing useful is in *out and the triangle must not be sent.
EncodeStatus encode_triangle(const RecordFormat& format, const VertexIn in[3], TriangleRecord* out);

// FIFO words of a triangle after its state word: u_offset, v_offset, q_exp, then per vertex
// x, y, z, q, uq[31:0], uq[63:32], vq[31:0], vq[63:32], rgba.
inline constexpr size_t kWordsPerVertex = 9;
inline constexpr size_t kTriangleWords = 3 + 3 * kWordsPerVertex;
void pack_triangle(const TriangleRecord& tri, uint32_t words[kTriangleWords]);
void unpack_triangle(const uint32_t words[kTriangleWords], TriangleRecord* tri);

}  // namespace htx::fw
