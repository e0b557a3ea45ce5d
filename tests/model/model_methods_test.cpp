// Perspective methods and the LOD unit, checked inside the raster unit against the exact quotients
// of the triangle's own planes.
#include <gtest/gtest.h>

#include <cmath>

#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/lod.hpp"
#include "htx/model/perspective.hpp"

namespace htx::model {
namespace {

constexpr int kW = 320, kH = 240;

fw::TriangleRecord perspective_triangle(const ModelConfig& cfg) {
  fw::VertexIn in[3];
  in[0].x = 10.5, in[0].y = 10.5, in[0].w = 1, in[0].u = 1000.25, in[0].v = -20;
  in[1].x = 300.5, in[1].y = 30.5, in[1].w = 3, in[1].u = 1300.5, in[1].v = 60;
  in[2].x = 40.5, in[2].y = 220.5, in[2].w = 8, in[2].u = 980, in[2].v = 150.75;
  fw::TriangleRecord rec;
  EXPECT_EQ(fw::encode_triangle(cfg.record_format(), in, &rec), fw::kEncodeOk);
  return rec;
}

// u = U / Q at the pixel, exactly, as a double (for comparisons only).
double exact_u(const TriangleUnit& t, int x, int y, bool v_axis) {
  const int64_t px = 256 * int64_t{x} + 128, py = 256 * int64_t{y} + 128;
  const i128 n = v_axis ? t.vq_plane().at(px, py) : t.uq_plane().at(px, py);
  const i128 q = t.q_plane().at(px, py);
  const i128 ip = n / q;
  return static_cast<double>(ip) + static_cast<double>(n - ip * q) / static_cast<double>(q);
}

struct Walk {
  std::vector<std::vector<int64_t>> u, v;
  std::vector<int> x0, x1;
};

Walk walk(const TriangleUnit& t, Method m) {
  Walk w;
  SpanCoords s;
  for (int y = t.y_lo(); y <= t.y_hi(); ++y) {
    int a, b;
    if (!t.span(y, &a, &b)) continue;
    t.span_coords(y, a, b, m, &s);
    w.u.push_back(s.u);
    w.v.push_back(s.v);
    w.x0.push_back(a);
    w.x1.push_back(b);
  }
  return w;
}

TEST(Methods, RecipNrAndLutAgainstTheExactQuotient) {
  for (const char* name : {"full", "icebreaker"}) {
    const ModelConfig& cfg = model_config(name);
    const TriangleUnit t(perspective_triangle(cfg), TriState{}, cfg, kW, kH);
    ASSERT_FALSE(t.empty());
    const double ulp = std::ldexp(1.0, -static_cast<int>(cfg.texcoord_frac_bits));
    const double lut_bound = std::ldexp(1.0 + std::ldexp(1.0, -static_cast<int>(cfg.recip_guard_bits + 1)),
                                        -static_cast<int>(cfg.recip_table_bits + 1));
    const double nr_bound = cfg.pixel_nr_steps == 1 ? std::ldexp(1.0, -17) : std::ldexp(1.0, -28);
    const Walk nr = walk(t, Method::RecipNr), lut = walk(t, Method::RecipLut);
    double worst_nr = 0, worst_lut = 0;
    size_t row = 0;
    for (int y = t.y_lo(); y <= t.y_hi(); ++y) {
      int a, b;
      if (!t.span(y, &a, &b)) continue;
      for (int x = a; x <= b; ++x) {
        const size_t k = static_cast<size_t>(x - a);
        for (bool vax : {false, true}) {
          const double e = exact_u(t, x, y, vax);
          const double got_nr = static_cast<double>((vax ? nr.v : nr.u)[row][k]) * ulp;
          const double got_lut = static_cast<double>((vax ? lut.v : lut.u)[row][k]) * ulp;
          // Allowed: the reciprocal's relative error on |u| plus one coordinate ulp.
          worst_nr = std::max(worst_nr, std::fabs(got_nr - e) / (std::fabs(e) * nr_bound + ulp));
          worst_lut = std::max(worst_lut, std::fabs(got_lut - e) / (std::fabs(e) * lut_bound + ulp));
        }
      }
      ++row;
    }
    EXPECT_LE(worst_nr, 1.0) << name;
    EXPECT_LE(worst_lut, 1.0) << name;
    EXPECT_GT(worst_lut, 0.05) << name;  // the table's error is visible, so the check can fail
  }
}

TEST(Methods, SubdivAndQuadraticAreExactAtTheirPoints) {
  const ModelConfig& cfg = model_config("full");
  for (unsigned n : {2u, 7u, 16u, 64u}) {
    TriState st;
    st.subdiv_n = n;
    const TriangleUnit t(perspective_triangle(cfg), st, cfg, kW, kH);
    const Walk nr = walk(t, Method::RecipNr), sd = walk(t, Method::Subdiv), qd = walk(t, Method::Quadratic);
    double err_sd = 0, err_qd = 0;
    for (size_t r = 0; r < nr.u.size(); ++r) {
      const size_t len = nr.u[r].size();
      for (size_t k = 0; k < len; ++k) {
        const bool exact_point = k % n == 0 || k + 1 == len;
        if (exact_point) {
          ASSERT_EQ(sd.u[r][k], nr.u[r][k]) << "n=" << n << " row " << r << " k " << k;
          ASSERT_EQ(sd.v[r][k], nr.v[r][k]);
          ASSERT_EQ(qd.u[r][k], nr.u[r][k]);
        }
        err_sd = std::max(err_sd, static_cast<double>(std::llabs(sd.u[r][k] - nr.u[r][k])));
        err_qd = std::max(err_qd, static_cast<double>(std::llabs(qd.u[r][k] - nr.u[r][k])));
      }
    }
    if (n == 2) {
      EXPECT_LE(err_qd, err_sd + 2);  // one pixel between exact points: both tiny
    }
    if (n >= 16) {
      EXPECT_LT(err_qd, err_sd / 4) << "n=" << n;  // the parabola follows the hyperbola better
    }
  }
}

TEST(Methods, AffineIsLinearInScreenSpaceThroughTheVertexCoordinates) {
  const ModelConfig& cfg = model_config("full");
  const fw::TriangleRecord rec = perspective_triangle(cfg);
  const TriangleUnit t(rec, TriState{}, cfg, kW, kH);
  const double ulp = std::ldexp(1.0, -static_cast<int>(cfg.texcoord_frac_bits));
  const double xs[3] = {10.5, 300.5, 40.5}, ys[3] = {10.5, 30.5, 220.5}, us[3] = {1000.25, 1300.5, 980};
  const double det = (xs[1] - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (ys[1] - ys[0]);
  SpanCoords s;
  for (int y : {11, 60, 150, 219}) {
    int a, b;
    ASSERT_TRUE(t.span(y, &a, &b));
    t.span_coords(y, a, b, Method::Affine, &s);
    for (int x = a; x <= b; x += 7) {
      const double px = x + 0.5, py = y + 0.5;
      const double l1 = ((px - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (py - ys[0])) / det;
      const double l2 = ((xs[1] - xs[0]) * (py - ys[0]) - (px - xs[0]) * (ys[1] - ys[0])) / det;
      const double want = us[0] + l1 * (us[1] - us[0]) + l2 * (us[2] - us[0]);
      EXPECT_NEAR(static_cast<double>(s.u[static_cast<size_t>(x - a)]) * ulp + rec.u_offset, want, 4 * ulp)
          << x << "," << y;
    }
  }
  // The depth plane passes through the vertex values.
  EXPECT_EQ(t.depth_at(256 * 10 + 128, 256 * 10 + 128), rec.v[0].z);
}

TEST(Lod, Log2UnitError) {
  for (unsigned n : {6u, 10u}) {
    const Log2Unit unit(n, 10);
    double worst = 0;
    for (uint64_t x = 1; x < (uint64_t{1} << 22); x += 97)
      worst = std::max(worst, std::fabs(std::ldexp(static_cast<double>(unit.log2(x)), -10) -
                                        std::log2(static_cast<double>(x))));
    // Midpoint table: at most log2(1 + 2^-(n+1)) + half an output ulp.
    EXPECT_LE(worst, std::log2(1 + std::ldexp(1.0, -static_cast<int>(n + 1))) + std::ldexp(1.0, -11)) << n;
    EXPECT_GT(worst, std::ldexp(1.0, -static_cast<int>(n + 3))) << n;
  }
  EXPECT_EQ(Log2Unit(8, 8).log2(1), 0 + Log2Unit::table_entry(8, 8, 0));
  EXPECT_EQ(Log2Unit(8, 8).log2(1024) >> 8, 10);
}

TEST(Lod, IsotropicLodOfKnownScales) {
  const Log2Unit unit(10, 10);
  LodInputs in;
  in.q = i128{1} << 30;
  in.tex_frac_bits = 16;
  in.u = 5 << 16;
  in.v = 7 << 16;
  // 4 texels per pixel along x in u, 2 along y in v (per subpixel: /256, times q).
  in.gux = (i128{1} << 30) / 64;
  in.gvy = (i128{1} << 30) / 128;
  EXPECT_NEAR(compute_lod(unit, in, 8) / 256.0, 2.0, 0.01);
  // du/dx = 3, dv/dx = 4: |(3, 4)| = 5 -> log2 5.
  in.gux = (i128{3} << 30) / 256;
  in.gvx = (i128{4} << 30) / 256;
  in.gvy = 0;
  EXPECT_NEAR(compute_lod(unit, in, 8) / 256.0, std::log2(5.0), 0.01);
  // Perspective: with dq/dx != 0 the derivative is (g_u - u g_q) / q.
  in.gux = (i128{1} << 30) / 256;  // 1 texel/pixel before the q term
  in.gvx = 0;
  in.gqx = (i128{1} << 30) / 2560;  // dq/dx = q/10 per pixel
  in.u = 20 << 16;                  // u = 20: du/dx = 1 - 20 * 0.1 = -1
  in.v = 0;                         // v = 0: dv/dx = 0
  EXPECT_NEAR(compute_lod(unit, in, 8) / 256.0, 0.0, 0.01);
  in.gux = in.gqx = 0;
  EXPECT_EQ(compute_lod(unit, in, 8), INT32_MIN);
}

TEST(Lod, BlockFloatingGradientsKeepTheLod) {
  const Log2Unit unit(10, 10);
  LodInputs in;
  in.q = i128{1} << 50;
  in.u = 123456;
  in.v = -98765;
  in.gux = (i128{3} << 50) / 256 + 12345;
  in.gvy = (i128{7} << 49) / 256 - 999;
  in.gqx = (i128{1} << 50) / 3000;
  in.gqy = -(i128{1} << 50) / 7000;
  const int32_t exact = compute_lod(unit, in, 8);
  const i128 g[6] = {in.gux, in.guy, in.gvx, in.gvy, in.gqx, in.gqy};
  const int s = lod_gradient_shift(g, 16);
  EXPECT_EQ(s, msb_index(static_cast<u128>(in.gux)) + 2 - 16);
  for (i128 x : g) EXPECT_LT(abs128(x >> s), i128{1} << 15);
  LodInputs b = in;
  b.gux = in.gux >> s, b.guy = in.guy >> s, b.gvx = in.gvx >> s, b.gvy = in.gvy >> s;
  b.gqx = in.gqx >> s, b.gqy = in.gqy >> s;
  b.grad_shift = s;
  EXPECT_NEAR(compute_lod(unit, b, 8), exact, 2);
  const i128 small[6] = {5, -3, 0, 0, 1, 0};
  EXPECT_EQ(lod_gradient_shift(small, 16), 0);
}

}  // namespace
}  // namespace htx::model
