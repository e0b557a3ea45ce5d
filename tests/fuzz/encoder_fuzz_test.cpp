// Robustness of the vertex-record encoders (docs/robustness.md, "Vertex-record encoders"): the
// double encoder (firmware/lib, htx::fw::encode_triangle) with NaN, infinities, w <= 0, huge and
// near-limit coordinates, and the fixed-point encoder (firmware/render, encode_triangle_fx) with
// arbitrary 32-bit inputs. This executable compiles both encoders' sources itself with
// -fsanitize=undefined -fno-sanitize-recover, so undefined behaviour aborts the test.
// Checked: the status is always one of the documented values, and every record produced with
// kEncodeOk has in-range fields that survive pack/unpack unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>
#include <random>

#include "htx/fw/vertex_record.h"
#include "htx/render/encode.h"
#include "htx/render/fixed.h"

namespace {

using htx::fw::EncodeStatus;
using htx::fw::RecordFormat;
using htx::fw::TriangleRecord;
using htx::fw::VertexIn;

const RecordFormat kFormats[] = {{16, 24, 32, 16}, {14, 16, 24, 13}, {2, 8, 8, 2}, {22, 24, 32, 24}};

bool documented(EncodeStatus s) { return s >= htx::fw::kEncodeOk && s <= htx::fw::kEncodeBadFormat; }

int64_t smin(unsigned bits) { return -(int64_t{1} << (bits - 1)); }
int64_t smax(unsigned bits) { return (int64_t{1} << (bits - 1)) - 1; }

// Every field of a successful record lies in its documented range, and pack/unpack is lossless.
void expect_in_range(const RecordFormat& f, const TriangleRecord& r, const char* what) {
  const unsigned xw = f.xy_int_bits + 8u;
  const int64_t q_top = (int64_t{1} << f.q_bits) - 1;
  const unsigned uvw = f.q_bits + f.uv_int_bits;
  EXPECT_LT(std::llabs(r.u_offset), int64_t{1} << 30) << what;
  EXPECT_LT(std::llabs(r.v_offset), int64_t{1} << 30) << what;
  uint32_t qmax = 0;
  for (const auto& v : r.v) {
    EXPECT_GE(v.x, smin(xw)) << what;
    EXPECT_LE(v.x, smax(xw)) << what;
    EXPECT_GE(v.y, smin(xw)) << what;
    EXPECT_LE(v.y, smax(xw)) << what;
    EXPECT_LE(v.z, static_cast<uint32_t>((int64_t{1} << f.z_bits) - 1)) << what;
    EXPECT_GE(v.q, 1u) << what;
    EXPECT_LE(v.q, static_cast<uint64_t>(q_top)) << what;
    EXPECT_GE(v.uq, smin(uvw)) << what;
    EXPECT_LE(v.uq, smax(uvw)) << what;
    EXPECT_GE(v.vq, smin(uvw)) << what;
    EXPECT_LE(v.vq, smax(uvw)) << what;
    if (v.q > qmax) qmax = v.q;
  }
  // The largest vertex q is normalised into [2^(q_bits-1), 2^q_bits).
  EXPECT_GE(qmax, uint32_t{1} << (f.q_bits - 1)) << what;
  uint32_t w[htx::fw::kTriangleWords];
  htx::fw::pack_triangle(r, w);
  TriangleRecord back;
  htx::fw::unpack_triangle(w, &back);
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

// A double from a menu of hostile values, or an ordinary one.
double hostile(std::mt19937& rng, double limit) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::uniform_real_distribution<double> ordinary(-2 * limit, 2 * limit);
  switch (rng() % 16) {
    case 0: return nan;
    case 1: return (rng() & 1u) ? inf : -inf;
    case 2: return (rng() & 1u) ? 1.7e308 : -1.7e308;
    case 3: return std::numeric_limits<double>::denorm_min() * ((rng() & 1u) ? 1 : -1);
    case 4: return 0.0;
    case 5: return -0.0;
    // Exact subpixel values at and below the limit, and values in the open window
    // (limit - 1/512, limit) that round up onto it (docs/robustness.md, "Defects these tests
    // found", 1: the encoder once let those wrap).
    case 6: {
      const double below[] = {0.0,        1.0 / 256,   2.0 / 256, 3.0 / 256,
                              1.0 / 1024, 1.0 / 65536, limit - std::nextafter(limit, 0.0)};
      const double v = limit - below[rng() % 7];
      return (rng() & 1u) ? v : -v;
    }
    case 7: return (limit + static_cast<double>(rng() % 4) / 256.0) * ((rng() & 1u) ? 1 : -1);
    case 8: return std::ldexp(1.0, static_cast<int>(rng() % 120) - 60) * ((rng() & 1u) ? 1 : -1);
    default: return std::round(ordinary(rng) * 256.0) / 256.0;
  }
}

TEST(EncoderFuzz, DoubleEncoderHostileInputs) {
  std::mt19937 rng(7);
  int ok = 0, counts[6] = {};
  for (int iter = 0; iter < 60000; ++iter) {
    const RecordFormat& f = kFormats[iter % 4];
    const double xy_limit = std::ldexp(1.0, f.xy_int_bits - 1);
    VertexIn in[3];
    for (auto& v : in) {
      v.x = (rng() % 3) ? std::round(std::uniform_real_distribution<double>(-100, 400)(rng) * 256) / 256
                        : hostile(rng, xy_limit);
      v.y = (rng() % 3) ? std::round(std::uniform_real_distribution<double>(-100, 400)(rng) * 256) / 256
                        : hostile(rng, xy_limit);
      v.z = (rng() % 4) ? std::uniform_real_distribution<double>(-0.5, 1.5)(rng) : hostile(rng, 1.0);
      v.w = (rng() % 4) ? std::uniform_real_distribution<double>(0.01, 100)(rng) : hostile(rng, 1e6);
      const double uv_limit = std::ldexp(1.0, f.uv_int_bits - 1);
      v.u = (rng() % 4) ? std::uniform_real_distribution<double>(-uv_limit / 2, uv_limit / 2)(rng)
                        : hostile(rng, std::ldexp(1.0, 30));
      v.v = (rng() % 4) ? std::uniform_real_distribution<double>(-uv_limit / 2, uv_limit / 2)(rng)
                        : hostile(rng, uv_limit);
      v.r = (rng() % 4) ? std::uniform_real_distribution<double>(-0.2, 1.2)(rng) : hostile(rng, 1.0);
      v.g = hostile(rng, 1.0);
      v.b = std::uniform_real_distribution<double>(0, 1)(rng);
      v.a = (rng() % 8) ? 1.0 : hostile(rng, 1.0);
    }
    TriangleRecord r;
    const EncodeStatus s = htx::fw::encode_triangle(f, in, &r);
    ASSERT_TRUE(documented(s)) << "status " << s;
    ASSERT_NE(s, htx::fw::kEncodeBadFormat);
    ++counts[s];
    // Inputs the documentation says must be refused.
    bool nonfinite = false, bad_w = false;
    for (const auto& v : in) {
      for (double d : {v.x, v.y, v.z, v.w, v.u, v.v}) nonfinite |= !std::isfinite(d) || std::fabs(d) >= 1.7e308;
      bad_w |= !(v.w > 0);
    }
    // A triangle with several problems reports one of them (the first vertex's, in the order
    // finiteness, then w); a status is never given without its cause.
    if (nonfinite || bad_w) {
      EXPECT_TRUE(s == htx::fw::kEncodeNotFinite || s == htx::fw::kEncodeBadW) << iter << " status " << s;
    }
    if (s == htx::fw::kEncodeNotFinite) {
      EXPECT_TRUE(nonfinite) << iter;
    }
    if (s == htx::fw::kEncodeBadW) {
      bool tiny_w = false;  // 1/w overflows: refused as a bad w
      for (const auto& v : in) tiny_w |= v.w > 0 && !(1.0 / v.w < 1.7e308);
      EXPECT_TRUE(bad_w || tiny_w) << iter;
    }
    if (s == htx::fw::kEncodeOk) {
      ++ok;
      for (int k = 0; k < 3; ++k) {
        EXPECT_LT(std::fabs(in[k].x), xy_limit) << iter;
        EXPECT_LT(std::fabs(in[k].y), xy_limit) << iter;
        // The record holds x and y rounded to 1/256 pixel, not wrapped.
        EXPECT_LE(std::fabs(static_cast<double>(r.v[k].x) - in[k].x * 256.0), 0.5) << iter << " x " << in[k].x;
        EXPECT_LE(std::fabs(static_cast<double>(r.v[k].y) - in[k].y * 256.0), 0.5) << iter << " y " << in[k].y;
      }
      expect_in_range(f, r, "double encoder");
      if (::testing::Test::HasFailure()) FAIL() << "iteration " << iter;
    }
  }
  // The menu must reach every outcome, or the test is not exercising what it claims.
  EXPECT_GT(ok, 2000);
  std::printf("double encoder: %d accepted; not finite %d, bad w %d, xy range %d, uv range %d\n", ok, counts[1],
              counts[2], counts[3], counts[4]);
  for (int s = 1; s <= 4; ++s) EXPECT_GT(counts[s], 100) << "status " << s;
}

TEST(EncoderFuzz, DoubleEncoderBadFormats) {
  std::mt19937 rng(8);
  VertexIn in[3];
  in[1].x = 10;
  in[2].y = 10;
  for (int iter = 0; iter < 2000; ++iter) {
    RecordFormat f{static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()),
                   static_cast<uint8_t>(rng())};
    const bool valid = f.xy_int_bits >= 2 && f.xy_int_bits <= 22 && f.z_bits >= 8 && f.z_bits <= 24 &&
                       f.q_bits >= 8 && f.q_bits <= 32 && f.uv_int_bits >= 2 && f.uv_int_bits <= 24;
    TriangleRecord r;
    const EncodeStatus s = htx::fw::encode_triangle(f, in, &r);
    if (!valid) EXPECT_EQ(s, htx::fw::kEncodeBadFormat);
    else EXPECT_TRUE(documented(s));
  }
}

// The fixed-point encoder with arbitrary 32-bit screen vertices (x, y, z, w, the reciprocal as
// the projection computes it, or an arbitrary one) and attributes.
TEST(EncoderFuzz, FixedPointEncoderArbitraryInputs) {
  std::mt19937 rng(9);
  int ok = 0, counts[6] = {};
  for (int iter = 0; iter < 60000; ++iter) {
    const RecordFormat& f = kFormats[iter % 4];
    const int32_t lim = int32_t{1} << (f.xy_int_bits + 7);
    htx::render::ClipVert cv[3];
    htx::render::ScreenVert sv[3];
    for (int k = 0; k < 3; ++k) {
      auto any32 = [&] { return static_cast<int32_t>(rng()); };
      cv[k].x = any32();
      cv[k].y = any32();
      cv[k].z = any32();
      cv[k].w = any32();
      cv[k].s = (rng() % 3) ? static_cast<int32_t>(rng() % 0x40000) - 0x20000 : any32();
      cv[k].t = (rng() % 3) ? static_cast<int32_t>(rng() % 0x40000) - 0x20000 : any32();
      for (int32_t& c : cv[k].c) c = (rng() % 2) ? static_cast<int32_t>(rng() % (256 << 16)) : any32();
      sv[k].x = (rng() % 2) ? static_cast<int32_t>(rng() % 200000) - 50000
                            : ((rng() % 2) ? any32() : ((rng() & 1u) ? lim - 1 - static_cast<int32_t>(rng() % 3)
                                                                     : -lim + static_cast<int32_t>(rng() % 3)));
      sv[k].y = (rng() % 2) ? static_cast<int32_t>(rng() % 200000) - 50000 : any32();
      sv[k].z = rng();
      sv[k].w = (rng() % 4) ? static_cast<int32_t>(1 + rng() % 0x7FFFFFFF) : any32();
      if (rng() % 8) {
        sv[k].inv_w = sv[k].w > 0 ? htx::render::reciprocal(static_cast<uint32_t>(sv[k].w)) : htx::render::Reciprocal{};
      } else {
        sv[k].inv_w.mant = rng();
        sv[k].inv_w.lz = static_cast<int>(rng() % 70) - 3;
      }
      sv[k].attr = &cv[k];
    }
    const htx::render::ScreenVert* pv[3] = {&sv[0], &sv[1], &sv[2]};
    const htx::render::TexSize tex{static_cast<uint8_t>(rng() % 17), static_cast<uint8_t>(rng() % 17)};
    TriangleRecord r;
    const EncodeStatus s = htx::render::encode_triangle_fx(f, pv, tex, &r);
    ASSERT_TRUE(documented(s)) << "status " << s;
    ++counts[s];
    if (tex.log2_width > 15 || tex.log2_height > 15) {
      EXPECT_EQ(s, htx::fw::kEncodeBadFormat);
      continue;
    }
    if (s == htx::fw::kEncodeOk) {
      ++ok;
      for (const auto& v : sv) {
        EXPECT_GT(v.w, 0);
        EXPECT_LT(std::abs(static_cast<int64_t>(v.x)), lim);
        EXPECT_LT(std::abs(static_cast<int64_t>(v.y)), lim);
      }
      // Records from a consistent reciprocal obey every range; an arbitrary reciprocal (inputs the
      // projection never produces) need only keep the encoder defined.
      bool consistent = true;
      for (const auto& v : sv) consistent &= v.inv_w.mant >= 0x80000000u && v.inv_w.lz >= 0 && v.inv_w.lz < 64;
      if (consistent) expect_in_range(f, r, "fixed-point encoder");
      if (::testing::Test::HasFailure()) FAIL() << "iteration " << iter;
    }
  }
  EXPECT_GT(ok, 150);
  std::printf("fixed-point encoder: %d accepted; bad w %d, xy range %d, uv range %d, bad format %d\n", ok,
              counts[2], counts[3], counts[4], counts[5]);
  for (int s = 2; s <= 5; ++s) EXPECT_GT(counts[s], 100) << "status " << s;
}

}  // namespace
