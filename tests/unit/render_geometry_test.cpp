// firmware/render's fixed-point geometry against the host's double-precision geometry stage
// (hw/model geometry.hpp) and the double vertex-record encoder (firmware/lib vertex_record.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/geometry.hpp"
#include "htx/model/scenes.hpp"
#include "htx/render/clip.h"
#include "htx/render/encode.h"
#include "htx/render/fixed.h"
#include "htx/render/pipeline.h"
#include "htx/render/transform.h"
#include "htx/render/vertex_transform.h"
#include "render_scene.hpp"

namespace {

using htx::test::to_q16;
constexpr double kQ = 1.0 / 65536.0;

double q16(int32_t v) { return v * kQ; }

// round_shift_u32 against the 64-bit rounding: every shift 0..63 on the values around each power
// of two and its halves, the ends and random words.
TEST(RenderFixed, UnsignedRoundShiftEqualsTheWideOne) {
  std::vector<uint32_t> values = {0u, 1u, 2u, 3u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  for (int b = 1; b < 32; ++b)
    for (int64_t d : {-1, 0, 1}) values.push_back(static_cast<uint32_t>((int64_t{1} << b) + d));
  std::mt19937 rng(3);
  for (int i = 0; i < 2000; ++i) values.push_back(static_cast<uint32_t>(rng()));
  for (uint32_t v : values) {
    for (int s = 0; s < 64; ++s) {
      const int64_t want = s == 0 ? int64_t{v} : htx::render::round_shift(static_cast<int64_t>(v), s);
      ASSERT_EQ(static_cast<int64_t>(htx::render::round_shift_u32(v, s)), want) << v << " >> " << s;
    }
  }
}

TEST(RenderFixed, ReciprocalHas31CorrectBits) {
  std::mt19937 rng(7);
  for (int i = 0; i < 200000; ++i) {
    uint32_t x = rng() >> (rng() % 32);
    if (x == 0) x = 1;
    const htx::render::Reciprocal r = htx::render::reciprocal(x);
    ASSERT_GE(r.mant, 0x80000000u);
    const double got = std::ldexp(static_cast<double>(r.mant), r.lz - 63);
    const double rel = std::fabs(got * x - 1.0);
    ASSERT_LT(rel, std::ldexp(1.0, -30)) << "x=" << x;
  }
  for (int k = 0; k < 32; ++k) {  // powers of two are exact
    const htx::render::Reciprocal r = htx::render::reciprocal(1u << k);
    EXPECT_EQ(std::ldexp(static_cast<double>(r.mant), r.lz - 63), std::ldexp(1.0, -k));
  }
}

htx::Mat4 random_matrix(std::mt19937& rng, double range) {
  std::uniform_real_distribution<double> d(-range, range);
  htx::Mat4 m;
  for (auto& row : m.m)
    for (double& e : row) e = d(rng);
  return m;
}

double entry(const htx::render::Mat4& m, int r, int c) {
  return std::ldexp(static_cast<double>(m.m[r][c]), -(c < 3 ? m.frac : 16));
}

TEST(RenderTransform, PointsAndProductsWithinTheirRoundingBounds) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-300, 300);
  for (int i = 0; i < 2000; ++i) {
    const htx::Mat4 m = random_matrix(rng, 4);
    const htx::render::Mat4 mf = htx::test::to_mat4_fx(m);
    ASSERT_GE(mf.frac, 27);  // |entries| < 4
    const int32_t x = to_q16(coord(rng)), y = to_q16(coord(rng)), z = to_q16(coord(rng));
    const htx::render::Vec4 p = htx::render::transform_point(mf, x, y, z);
    const int32_t in[3] = {x, y, z};
    const int32_t got[4] = {p.x, p.y, p.z, p.w};
    const double half_ulp_m = std::ldexp(0.5, -mf.frac);
    for (int r = 0; r < 4; ++r) {
      // Against the exact product of the quantised inputs: one final rounding. Against the
      // unquantised matrix: plus half an ulp per entry times the coordinate.
      double exact_q = entry(mf, r, 3), exact = m.m[static_cast<size_t>(r)][3], bound = kQ / 2 + kQ / 2;
      for (int c = 0; c < 3; ++c) {
        exact_q += entry(mf, r, c) * q16(in[c]);
        exact += m.m[static_cast<size_t>(r)][static_cast<size_t>(c)] * q16(in[c]);
        bound += std::fabs(q16(in[c])) * half_ulp_m;
      }
      ASSERT_LE(std::fabs(q16(got[r]) - exact_q), kQ / 2 + 1e-12);
      ASSERT_LE(std::fabs(q16(got[r]) - exact), bound + 1e-12);
    }
  }
  for (int i = 0; i < 200; ++i) {
    const htx::Mat4 a = random_matrix(rng, 3), b = random_matrix(rng, 3);
    const htx::render::Mat4 pf = htx::render::mat4_mul(htx::test::to_mat4_fx(a), htx::test::to_mat4_fx(b));
    const htx::Mat4 p = a * b;
    // Inputs quantised to 2^-28 (linear) and 2^-17 (translation), four products each rounded.
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        ASSERT_NEAR(entry(pf, r, c), p.m[static_cast<size_t>(r)][static_cast<size_t>(c)], 4 * 3 * kQ / 2 + 4 * kQ);
  }
  // A projection's depth row keeps its precision through the product (far/near = 4000).
  const htx::Mat4 proj = htx::perspective(0.8, 4.0 / 3.0, 0.1, 400);
  const htx::Mat4 view = htx::look_at({0, 1, 0}, {0, 0.86, -1}, {0, 1, 0});
  const htx::render::Mat4 vp = htx::render::mat4_mul(htx::test::to_mat4_fx(proj), htx::test::to_mat4_fx(view));
  const htx::Mat4 vpd = proj * view;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(entry(vp, 2, c), vpd.m[2][static_cast<size_t>(c)], 1e-7);
}

// Every angle of a whole turn (Q16 turns) against the library's sin and cos; the rotation matrix
// built from them turns x towards -z and leaves y alone.
TEST(RenderTransform, SinCosOfEveryAngleWithinThreeUnitsOfQ30) {
  double worst = 0;
  for (uint32_t t = 0; t <= 0x10000u; ++t) {
    int32_t s = 0, c = 0;
    htx::render::sin_cos_turns(t, &s, &c);
    const double a = 2 * M_PI * static_cast<double>(t) / 65536.0;
    worst = std::max({worst, std::abs(s - std::sin(a) * 0x1p30), std::abs(c - std::cos(a) * 0x1p30)});
  }
  EXPECT_LE(worst, 3.0);
  int32_t s = 0, c = 0;
  htx::render::sin_cos_turns(0, &s, &c);
  EXPECT_EQ(s, 0);
  EXPECT_EQ(c, 1 << 30);
  htx::render::sin_cos_turns(0x4000, &s, &c);  // a quarter turn
  EXPECT_EQ(s, 1 << 30);
  EXPECT_EQ(c, 0);
  const htx::render::Mat4 r = htx::render::mat4_rotation_y(0x2000);  // an eighth of a turn
  const htx::render::Vec4 p = htx::render::transform_point(r, to_q16(2.0), to_q16(3.0), 0);
  EXPECT_NEAR(q16(p.x), std::sqrt(2.0), 2 * kQ);
  EXPECT_NEAR(q16(p.y), 3.0, kQ);
  EXPECT_NEAR(q16(p.z), -std::sqrt(2.0), 2 * kQ);
  EXPECT_EQ(p.w, 1 << 16);
}

// A turn about a vertical line away from the origin (`spin`): points on the line stay put, others
// turn about it as about the origin, and a whole turn is the identity.
TEST(RenderTransform, RotationAboutAVerticalLineKeepsThatLine) {
  const int32_t cx = to_q16(3.0), cz = to_q16(-5.0);
  for (uint32_t turn : {0x0u, 0x1555u, 0x4000u, 0x9000u, 0xFFFFu, 0x10000u}) {
    const htx::render::Mat4 r = htx::render::mat4_rotation_y_about(turn, cx, cz);
    const htx::render::Vec4 on = htx::render::transform_point(r, cx, to_q16(7.0), cz);
    EXPECT_NEAR(q16(on.x), 3.0, kQ) << turn;
    EXPECT_NEAR(q16(on.y), 7.0, kQ) << turn;
    EXPECT_NEAR(q16(on.z), -5.0, kQ) << turn;
    // (1, 2, 0) from the line, turned as mat4_rotation_y turns it about the origin.
    const htx::render::Vec4 off = htx::render::transform_point(r, cx + to_q16(1.0), to_q16(2.0), cz);
    const double a = 2 * M_PI * turn / 65536.0;
    EXPECT_NEAR(q16(off.x), 3.0 + std::cos(a), 2 * kQ) << turn;
    EXPECT_NEAR(q16(off.y), 2.0, kQ) << turn;
    EXPECT_NEAR(q16(off.z), -5.0 - std::sin(a), 2 * kQ) << turn;
    EXPECT_EQ(off.w, 1 << 16);
  }
  const htx::render::Mat4 whole = htx::render::mat4_rotation_y_about(0x10000u, cx, cz);
  const htx::render::Vec4 p = htx::render::transform_point(whole, to_q16(-1.25), to_q16(0.5), to_q16(9.0));
  EXPECT_EQ(p.x, to_q16(-1.25));
  EXPECT_EQ(p.z, to_q16(9.0));
}

TEST(RenderTransform, PerVertexHighProductsWithinThreeUlps) {
  std::mt19937 rng(17);
  const double ranges[3] = {1.5, 40, 400};
  for (double range : ranges) {
    std::uniform_real_distribution<double> coord(-range, range);
    for (int i = 0; i < 2000; ++i) {
      const htx::render::Mat4 mf = htx::test::to_mat4_fx(random_matrix(rng, 3));
      int32_t pts[3][3];
      for (auto& p : pts)
        for (int32_t& c : p) c = to_q16(coord(rng));
      const int bits = htx::render::position_int_bits(&pts[0][0], 3, 3);
      ASSERT_LE(std::ldexp(std::fabs(coord.max()), 0), std::ldexp(1.0, bits + 1));
      const htx::render::VertexTransform vt = htx::render::make_vertex_transform(mf, bits);
      EXPECT_EQ(vt.out_shift, 0);
      for (const auto& p : pts) {
        const htx::render::Vec4 got = htx::render::apply(vt, p[0], p[1], p[2]);
        const htx::render::Vec4 ref = htx::render::transform_point(mf, p[0], p[1], p[2]);
        // Matrix entries requantised to F = 48 - P bits (half an ulp times |p| < 2^P: 1/2 ulp of
        // Q16.16 per term) and three truncated products (< 1 ulp each).
        EXPECT_LE(std::abs(got.x - ref.x), 5) << range;
        EXPECT_LE(std::abs(got.y - ref.y), 5) << range;
        EXPECT_LE(std::abs(got.z - ref.z), 5) << range;
        EXPECT_LE(std::abs(got.w - ref.w), 5) << range;
      }
    }
  }
}

// What make_mesh_transform makes of view_proj * model for a vertex, against the double product:
// the same clip coordinates times 2^-down (mesh_mvp's), within `ulps` at that scale, so that
// the projected point is the same; and w keeps its sign.
void expect_mesh_transform_scales(const htx::Mat4& view_proj, const htx::Mat4& model, htx::Vec3 p, int expect_down,
                                  double ulps) {
  const int32_t xyz[3] = {to_q16(p.x), to_q16(p.y), to_q16(p.z)};
  const int bits = htx::render::position_int_bits(xyz, 1, 3);
  const htx::render::Mat4 vp_fx = htx::test::to_mat4_fx(view_proj), model_fx = htx::test::to_mat4_fx(model);
  int down = -1;
  htx::render::mesh_mvp(vp_fx, model_fx, bits, &down);
  EXPECT_EQ(down, expect_down);
  const htx::render::VertexTransform vt = htx::render::make_mesh_transform(vp_fx, model_fx, bits);
  const htx::render::Vec4 got = htx::render::apply(vt, xyz[0], xyz[1], xyz[2]);
  const htx::Vec4 want = (view_proj * model) * htx::Vec4{p.x, p.y, p.z, 1.0};
  ASSERT_GT(want.w, 0);
  ASSERT_GT(got.w, 0) << "w wrapped: " << q16(got.w) << " for " << want.w;
  const double scale = std::ldexp(1.0, -down);
  EXPECT_NEAR(q16(got.x), want.x * scale, ulps * kQ);
  EXPECT_NEAR(q16(got.y), want.y * scale, ulps * kQ);
  EXPECT_NEAR(q16(got.z), want.z * scale, ulps * kQ);
  EXPECT_NEAR(q16(got.w), want.w * scale, ulps * kQ);
}

// Positions below 2^14 and matrices the host accepts can still take clip coordinates past Q16.16:
// the mesh's transform is then scaled down (a positive scale moves no projected point), where the
// sums used to wrap.
TEST(RenderGeometry, ClipCoordinatesBeyondQ16AreScaledNotWrapped) {
  // A cube 16,000 across seen from 30,000 away: its far corner's w is 38,000.
  htx::Mat4 far_view = htx::Mat4::identity();
  far_view.m[3][2] = -1.0;  // w = -z + 30,000
  far_view.m[3][3] = 30000.0;
  expect_mesh_transform_scales(far_view, htx::Mat4::identity(), {8000, -8000, -8000}, 1, 4);
  expect_mesh_transform_scales(far_view, htx::Mat4::identity(), {-8000, 8000, 8000}, 1, 4);
  // A model scale of 16,385 (an entry the matrix can hold only at its least precision, which the
  // per-vertex form used to double past 2^31): clip x = 8,192.5 at w = 1.
  expect_mesh_transform_scales(htx::Mat4::identity(), htx::scale({16385, 16385, 1}), {0.5, -0.5, 0.25}, 0, 4);
  // Two translations the host accepts whose sum leaves Q16.16 (30,000 + 10,000).
  expect_mesh_transform_scales(htx::translate({30000, 0, 0}), htx::translate({10000, 0, 0}), {1, 2, 3}, 1, 4);
  // A scene well inside the range keeps its transform (its frames do not change).
  const htx::Mat4 vp = htx::perspective(1.0, 4.0 / 3.0, 0.5, 100.0) * htx::translate({0, 0, -5});
  expect_mesh_transform_scales(vp, htx::scale({2, 2, 2}), {1.5, -2, -3}, 0, 8);
}

// A projective model matrix with entries near 2^15 (only a crafted upload comes close; no scene
// the host builds does) needs more than 31 halvings before its clip coordinates fit Q16.16:
// mesh_mvp stopped at 31 and the sums wrapped (clip y 30,894 for -34,642).
TEST(RenderGeometry, AnyMatrixIsScaledUntilItsClipCoordinatesFit) {
  const htx::render::Mat4 view_proj{{{0, -2097152, 1024, 0},
                                     {INT32_MAX, INT32_MAX, 0, INT32_MAX},
                                     {INT32_MIN, INT32_MIN, -72, -1311489185},
                                     {-1, -131072, INT32_MAX, INT32_MAX}},
                                    17};
  const htx::render::Mat4 model{{{INT32_MAX, 1073741824, -1048576, 1980606561},
                                 {-64, -92346492, INT32_MIN, 0},
                                 {-4, -536870912, INT32_MIN, 4698496},
                                 {INT32_MAX, INT32_MAX, INT32_MIN, -64}},
                                16};
  const int32_t p[3] = {-1073741823, -1073741823, 1073741823};  // (-16384, -16384, 16384) - 1 ulp
  int down = 0;
  const htx::render::Mat4 mvp = htx::render::mesh_mvp(view_proj, model, 14, &down);
  EXPECT_GT(down, 31);
  const htx::render::Vec4 got =
      htx::render::apply(htx::render::make_vertex_transform(mvp, 14), p[0], p[1], p[2]);
  const int32_t rows[4] = {got.x, got.y, got.z, got.w};
  for (int i = 0; i < 4; ++i) {
    double exact = q16(mvp.m[i][3]);
    for (int j = 0; j < 3; ++j) exact += std::ldexp(static_cast<double>(mvp.m[i][j]), -mvp.frac) * q16(p[j]);
    EXPECT_NEAR(q16(rows[i]), exact, 8 * kQ) << "row " << i;
  }
}

// Rounded cut points can make a triangle a few ulps across non-convex, so that a later plane cuts
// it more than twice: a polygon that would not fit is dropped whole (the clipper wrote past its
// buffer there), and any smaller one keeps every vertex and cut point.
TEST(RenderGeometry, AClippedPolygonThatWouldNotFitIsDropped) {
  auto raw = [](int32_t x, int32_t y, int32_t z, int32_t w) {
    htx::render::ClipVert v{};
    v.x = x;
    v.y = y;
    v.z = z;
    v.w = w;
    return v;
  };
  auto clip = [](const htx::render::ClipVert (&tri)[3], htx::render::ClipPolygon* poly) {
    poly->count = 3;
    uint32_t planes = 0;
    for (int k = 0; k < 3; ++k) {
      poly->v[k] = tri[k];
      planes |= htx::render::outcode(tri[k]);
    }
    return htx::render::clip_polygon(poly, planes & htx::render::kOutcodePlanes);
  };
  htx::render::ClipPolygon poly;
  const htx::render::ClipVert too_many[3] = {raw(4, 4, -3, 2), raw(-3, -4, -2, 1), raw(-2, 1, -3, 3)};
  EXPECT_EQ(clip(too_many, &poly), htx::render::kClipTooManyVertices);
  EXPECT_EQ(poly.count, 0);
  // Tiny random triangles in raw units: a result fits, or the polygon is dropped and said to be.
  std::mt19937 rng(21);
  std::uniform_int_distribution<int32_t> c(-5, 5), w(1, 4);
  int kept = 0;
  for (int i = 0; i < 200000; ++i) {
    const htx::render::ClipVert tri[3] = {raw(c(rng), c(rng), c(rng), w(rng)), raw(c(rng), c(rng), c(rng), w(rng)),
                                          raw(c(rng), c(rng), c(rng), w(rng))};
    const htx::render::ClipResult r = clip(tri, &poly);
    ASSERT_TRUE(poly.count == 0 || (poly.count >= 3 && poly.count <= htx::render::kMaxClipVerts)) << poly.count;
    if (r == htx::render::kClipTooManyVertices) {
      ASSERT_EQ(poly.count, 0);
    }
    kept += poly.count > 0;
  }
  EXPECT_GT(kept, 1000);
}

htx::render::ClipVert clip_vert(double x, double y, double z, double w, double s, double t, double r) {
  htx::render::ClipVert v{};
  v.x = to_q16(x);
  v.y = to_q16(y);
  v.z = to_q16(z);
  v.w = to_q16(w);
  v.s = to_q16(s);
  v.t = to_q16(t);
  v.c[0] = to_q16(r * 255);
  v.c[1] = v.c[2] = v.c[3] = 255 << 16;
  return v;
}

htx::ClipVertex to_double(const htx::render::ClipVert& v) {
  htx::ClipVertex d;
  d.pos = {q16(v.x), q16(v.y), q16(v.z), q16(v.w)};
  d.s = q16(v.s);
  d.t = q16(v.t);
  d.r = q16(v.c[0]) / 255;
  return d;
}

// Clips the same triangle with both stages and compares vertex by vertex.
void expect_clip_matches(const htx::render::ClipVert in[3], int* vertices_out, double tol) {
  htx::render::ClipPolygon poly;
  poly.count = 3;
  std::vector<htx::ClipVertex> dpoly;
  uint32_t planes = 0;
  for (int k = 0; k < 3; ++k) {
    poly.v[k] = in[k];
    dpoly.push_back(to_double(in[k]));
    planes |= htx::render::outcode(in[k]);
  }
  htx::render::clip_polygon(&poly, planes);
  const std::vector<htx::ClipVertex> ref = htx::clip_polygon(dpoly);
  ASSERT_EQ(static_cast<size_t>(poly.count), ref.size());
  *vertices_out = poly.count;
  for (int k = 0; k < poly.count; ++k) {
    const htx::render::ClipVert& v = poly.v[k];
    ASSERT_GT(v.w, 0) << "a vertex with w <= 0 left the clipper";
    EXPECT_NEAR(q16(v.x), ref[static_cast<size_t>(k)].pos.x, tol);
    EXPECT_NEAR(q16(v.y), ref[static_cast<size_t>(k)].pos.y, tol);
    EXPECT_NEAR(q16(v.z), ref[static_cast<size_t>(k)].pos.z, tol);
    EXPECT_NEAR(q16(v.w), ref[static_cast<size_t>(k)].pos.w, tol);
    EXPECT_NEAR(q16(v.s), ref[static_cast<size_t>(k)].s, tol);
    EXPECT_NEAR(q16(v.t), ref[static_cast<size_t>(k)].t, tol);
    EXPECT_NEAR(q16(v.c[0]) / 255, ref[static_cast<size_t>(k)].r, tol);
    // On the inside of every plane, up to the rounding of the cut.
    for (int p = 0; p < 6; ++p) EXPECT_GE(htx::clip_plane_distance(to_double(v), p), -tol) << "plane " << p;
  }
}

TEST(RenderClip, TriangleCrossingEachPlaneMatchesTheDoubleClipper) {
  // One vertex beyond plane p, two inside: the polygon gains a vertex (quad).
  for (int p = 0; p < 6; ++p) {
    const int axis = p / 2;
    const double sign = (p % 2) ? 1.0 : -1.0;
    double out[3] = {0.1, 0.2, 0.3};
    out[axis] = sign * 3.0;  // |coord| = 3 > w = 2
    const htx::render::ClipVert tri[3] = {clip_vert(out[0], out[1], out[2], 2.0, 1.0, 0.0, 1.0),
                                          clip_vert(0.5, -0.5, 0.2, 2.0, 0.0, 0.0, 0.0),
                                          clip_vert(-0.5, 0.5, -0.2, 2.5, 0.0, 1.0, 0.5)};
    EXPECT_EQ(htx::render::outcode(tri[0]), 1u << p);
    int n = 0;
    SCOPED_TRACE("plane " + std::to_string(p));
    expect_clip_matches(tri, &n, 4 * kQ);
    EXPECT_EQ(n, 4);
  }
}

TEST(RenderClip, BehindTheEyeNeverReachesTheRasterUnit) {
  // Vertices with w < 0 (behind the camera): after the near plane z >= -w every vertex has w > 0.
  const htx::render::ClipVert tri[3] = {clip_vert(0.2, 0.1, -1.5, -1.0, 0, 0, 1),
                                        clip_vert(0.3, -0.2, 0.5, 1.0, 1, 0, 0),
                                        clip_vert(-0.4, 0.3, 0.8, 1.5, 0, 1, 0.5)};
  int n = 0;
  expect_clip_matches(tri, &n, 4 * kQ);
  EXPECT_GE(n, 3);
  // Entirely behind: nothing left.
  const htx::render::ClipVert behind[3] = {clip_vert(0, 0, 1, -1, 0, 0, 0), clip_vert(1, 0, 1, -2, 0, 0, 0),
                                           clip_vert(0, 1, 1, -1.5, 0, 0, 0)};
  htx::render::ClipPolygon poly;
  poly.count = 3;
  uint32_t planes = 0;
  for (int k = 0; k < 3; ++k) {
    poly.v[k] = behind[k];
    planes |= htx::render::outcode(behind[k]);
  }
  htx::render::clip_polygon(&poly, planes);
  EXPECT_EQ(poly.count, 0);
}

TEST(RenderClip, RandomTrianglesAgreeAndKeepWPositive) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> c(-3, 3), w(-1, 3), a(0, 1);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    htx::render::ClipVert tri[3];
    for (auto& v : tri) v = clip_vert(c(rng), c(rng), c(rng), w(rng), a(rng), a(rng), a(rng));
    // Skip slivers where a vertex lies within the rounding of a plane (the two clippers may then
    // legitimately keep or drop a zero-area piece).
    bool near_plane = false;
    for (const auto& v : tri)
      for (int p = 0; p < 6; ++p) near_plane |= std::fabs(htx::clip_plane_distance(to_double(v), p)) < 1e-3;
    if (near_plane) continue;
    int n = 0;
    SCOPED_TRACE("triangle " + std::to_string(i));
    // Each cut rounds its vertex to Q16.16 and the next cut starts from the rounded values; an edge
    // nearly parallel to a later plane amplifies that. 2^-10 bounds these random triangles.
    expect_clip_matches(tri, &n, 1.0 / 1024);
    if (HasFatalFailure()) return;
    ++compared;
  }
  EXPECT_GT(compared, 2500);
}

TEST(RenderProject, MatchesTheDoubleViewportWithinOneSubpixel) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> w(0.1, 300), f(-1, 1);
  const int sizes[3][2] = {{320, 240}, {160, 120}, {4096, 4096}};
  for (const auto& size : sizes) {
    for (int i = 0; i < 5000; ++i) {
      const double ww = w(rng);
      const htx::render::ClipVert v = clip_vert(f(rng) * ww, f(rng) * ww, f(rng) * ww, ww, 0, 0, 0);
      htx::render::ScreenVert s;
      htx::render::project(v, {size[0], size[1]}, &s);
      const htx::ScreenVertex d = htx::to_screen(to_double(v), size[0], size[1], 1, 1);
      // The double stage snaps to 1/256 (ties to even), ours rounds ties up after a 2^-30 divide.
      ASSERT_LE(std::fabs(s.x / 256.0 - d.x), 1.0 / 256 + 1e-9) << ww;
      ASSERT_LE(std::fabs(s.y / 256.0 - d.y), 1.0 / 256 + 1e-9) << ww;
      ASSERT_NEAR(std::ldexp(static_cast<double>(s.z), -32), d.z, std::ldexp(1.0, -28));
    }
  }
}

// A vertex on the near plane (z = -w, where the clipper puts its cut points) gets the nearest depth
// and one on the far plane the farthest, for every w: the reciprocal of w can be a unit above 1/w,
// which put c/w a unit below -1, and the near plane's depth wrapped to the far end (0xFFFFFFFF) for
// 660,797 of the first 2^20 values of w.
TEST(RenderProject, VerticesOnTheNearAndFarPlanesGetTheExtremeDepths) {
  std::mt19937 rng(23);
  std::uniform_int_distribution<int32_t> any_w(1, INT32_MAX);
  htx::render::ScreenVert s;
  for (int i = 1; i <= (1 << 21); ++i) {
    htx::render::ClipVert v{};
    v.w = i <= (1 << 20) ? i : any_w(rng);
    v.z = -v.w;
    htx::render::project(v, {320, 240}, &s);
    ASSERT_LE(s.z, 16u) << "near plane at w = " << v.w;
    v.z = v.w;
    htx::render::project(v, {320, 240}, &s);
    ASSERT_GE(s.z, 0xFFFFFFF0u) << "far plane at w = " << v.w;
  }
}

TEST(RenderCull, BackFacesAndDegenerateTrianglesAreNotSent) {
  // A unit-depth triangle in clip space, counter-clockwise in NDC (front), and the same reversed.
  const htx::render::MeshVertex verts[4] = {{to_q16(-0.5), to_q16(-0.5), 0, 0, 0, 0xFFFFFFFFu},
                                            {to_q16(0.5), to_q16(-0.5), 0, 0, 0, 0xFFFFFFFFu},
                                            {to_q16(0.0), to_q16(0.5), 0, 0, 0, 0xFFFFFFFFu},
                                            {to_q16(0.25), to_q16(-0.5), 0, 0, 0, 0xFFFFFFFFu}};
  const uint16_t idx[9] = {0, 1, 2, 0, 2, 1, 0, 1, 3};  // front, back, degenerate (collinear)
  htx::render::Mesh mesh{};
  mesh.vertices = verts;
  mesh.vertex_count = 4;
  mesh.indices = idx;
  mesh.triangle_count = 3;
  mesh.model = htx::render::mat4_identity();
  mesh.state.textured = false;
  mesh.position_bits = static_cast<int8_t>(htx::render::mesh_position_bits(verts, 4));
  htx::render::ClipVert clip[4];
  htx::render::ScreenVert screen[4];
  uint8_t codes[4];
  htx::render::VertexCache cache{clip, screen, codes, 4};
  std::vector<uint32_t> states;
  const htx::render::TriangleSink sink{
      [](void* ctx, uint32_t state, const uint32_t*) { static_cast<std::vector<uint32_t>*>(ctx)->push_back(state); },
      &states};
  htx::render::FrameParams frame;
  frame.viewport = {64, 64};
  htx::render::DrawStats st;
  ASSERT_EQ(htx::render::draw_mesh(frame, htx::render::mat4_identity(), mesh, &cache, sink, &st), htx::render::kDrawOk);
  EXPECT_EQ(st.sent, 1u);
  EXPECT_EQ(st.culled, 1u);
  EXPECT_EQ(st.degenerate, 1u);
  frame.cull_backfaces = false;
  htx::render::DrawStats st2;
  ASSERT_EQ(htx::render::draw_mesh(frame, htx::render::mat4_identity(), mesh, &cache, sink, &st2), htx::render::kDrawOk);
  EXPECT_EQ(st2.sent, 2u);
  EXPECT_EQ(st2.culled, 0u);
  // Bad input is refused with a status, nothing drawn.
  const uint16_t bad_idx[3] = {0, 1, 9};
  mesh.indices = bad_idx;
  mesh.triangle_count = 1;
  EXPECT_EQ(htx::render::draw_mesh(frame, htx::render::mat4_identity(), mesh, &cache, sink, &st2),
            htx::render::kDrawBadIndex);
  cache.capacity = 2;
  EXPECT_EQ(htx::render::draw_mesh(frame, htx::render::mat4_identity(), mesh, &cache, sink, &st2),
            htx::render::kDrawCacheTooSmall);
  EXPECT_EQ(states.size(), 3u);
}

// The fixed encoder against the double encoder fed with exactly the values the fixed one sees.
TEST(RenderEncode, FixedEncoderWithinBoundsOfTheDoubleEncoder) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> w(0.1, 200), f(-1, 1), st(-40, 40), col(0, 1);
  const htx::fw::RecordFormat formats[2] = {{16, 24, 32, 16}, {12, 16, 24, 13}};
  int compared = 0;
  for (const auto& fmt : formats) {
    for (int i = 0; i < 4000; ++i) {
      htx::render::ScreenVert sv[3];
      htx::render::ClipVert cv[3];
      htx::fw::VertexIn in[3];
      const double s0 = st(rng), t0 = st(rng);
      for (int k = 0; k < 3; ++k) {
        const double ww = w(rng);
        cv[k] = clip_vert(f(rng) * ww, f(rng) * ww, f(rng) * ww, ww, s0 + f(rng), t0 + f(rng), col(rng));
        htx::render::project(cv[k], {320, 240}, &sv[k]);
        in[k].x = sv[k].x / 256.0;
        in[k].y = sv[k].y / 256.0;
        in[k].z = std::ldexp(static_cast<double>(sv[k].z), -32);
        in[k].w = q16(sv[k].w);
        in[k].u = q16(cv[k].s) * 64;
        in[k].v = q16(cv[k].t) * 64;
        in[k].r = q16(cv[k].c[0]) / 255;
        in[k].g = in[k].b = in[k].a = 1.0;
      }
      const htx::render::ScreenVert* pv[3] = {&sv[0], &sv[1], &sv[2]};
      htx::fw::TriangleRecord got, ref;
      const auto gs = htx::render::encode_triangle_fx(fmt, pv, {6, 6}, &got);
      const auto rs = htx::fw::encode_triangle(fmt, in, &ref);
      ASSERT_EQ(gs, rs);
      if (gs != htx::fw::kEncodeOk) continue;
      ++compared;
      ASSERT_EQ(got.u_offset, ref.u_offset);
      ASSERT_EQ(got.v_offset, ref.v_offset);
      ASSERT_EQ(got.q_exp, ref.q_exp);
      for (int k = 0; k < 3; ++k) {
        const htx::fw::VertexRecord &a = got.v[k], &b = ref.v[k];
        ASSERT_EQ(a.x, b.x);
        ASSERT_EQ(a.y, b.y);
        ASSERT_LE(std::abs(static_cast<int64_t>(a.z) - static_cast<int64_t>(b.z)), 1);
        // q: the reciprocal's 2^-30 relative error, at most 2 units of the largest q plus rounding.
        const int64_t dq = static_cast<int64_t>(a.q) - static_cast<int64_t>(b.q);
        ASSERT_LE(std::abs(dq), 3) << "q " << a.q << " vs " << b.q;
        // uq = round(ul * q): off by |ul| * |dq| plus one rounding each.
        const double ul = in[k].u - ref.u_offset, vl = in[k].v - ref.v_offset;
        ASSERT_LE(std::fabs(static_cast<double>(a.uq - b.uq)), std::fabs(ul) * std::abs(dq) + 1.0);
        ASSERT_LE(std::fabs(static_cast<double>(a.vq - b.vq)), std::fabs(vl) * std::abs(dq) + 1.0);
        ASSERT_LE(std::abs(static_cast<int>(a.rgba & 0xFF) - static_cast<int>(b.rgba & 0xFF)), 1);
        ASSERT_EQ(a.rgba >> 8, b.rgba >> 8);
      }
    }
  }
  EXPECT_GT(compared, 7000);
}

// Three screen vertices at the origin, w = 1, each with its clip vertex (all zero): a triangle
// the encoder takes, for tests that change one field at a time.
struct FlatTriangle {
  htx::render::ScreenVert sv[3] = {};
  htx::render::ClipVert cv[3] = {};
  const htx::render::ScreenVert* pv[3] = {&sv[0], &sv[1], &sv[2]};
  FlatTriangle() {
    for (int k = 0; k < 3; ++k) {
      sv[k].w = htx::render::kOne;
      sv[k].inv_w = htx::render::reciprocal(static_cast<uint32_t>(sv[k].w));
      sv[k].attr = &cv[k];
    }
  }
  FlatTriangle(const FlatTriangle&) = delete;  // pv and attr point into this object
  FlatTriangle& operator=(const FlatTriangle&) = delete;
};

TEST(RenderEncode, RefusesWhatTheRecordCannotHold) {
  FlatTriangle t;
  auto& sv = t.sv;
  auto& cv = t.cv;
  auto& pv = t.pv;
  htx::fw::TriangleRecord rec;
  const htx::fw::RecordFormat fmt{14, 16, 24, 13};
  EXPECT_EQ(htx::render::encode_triangle_fx(fmt, pv, {}, &rec), htx::fw::kEncodeOk);
  sv[1].x = 8192 * 256;  // +2^13 pixels: outside 14 integer bits
  EXPECT_EQ(htx::render::encode_triangle_fx(fmt, pv, {}, &rec), htx::fw::kEncodeXyRange);
  sv[1].x = 0;
  cv[2].s = 9000 * htx::render::kOne;  // 9000 texels of span: +-4500 around the offset, beyond 13 bits
  EXPECT_EQ(htx::render::encode_triangle_fx(fmt, pv, {}, &rec), htx::fw::kEncodeUvRange);
  cv[2].s = 0;
  sv[0].w = 0;
  EXPECT_EQ(htx::render::encode_triangle_fx(fmt, pv, {}, &rec), htx::fw::kEncodeBadW);
  const htx::fw::RecordFormat bad{14, 16, 40, 13};
  EXPECT_EQ(htx::render::encode_triangle_fx(bad, pv, {}, &rec), htx::fw::kEncodeBadFormat);
}

// A colour channel is round(c / 2^16) clamped to 0..255 (Q16.16 in, 8 bits out), computed in 32
// bits: against the 64-bit rounding on the values around every edge (halves, 0, 255, the int32
// ends).
TEST(RenderEncode, ColourChannelsRoundAndClampAtEveryEdge) {
  FlatTriangle t;
  auto& cv = t.cv;
  auto& pv = t.pv;
  const htx::fw::RecordFormat fmt{14, 16, 24, 13};
  std::vector<int32_t> values = {INT32_MIN, INT32_MIN + 1, INT32_MAX - 1, INT32_MAX};
  for (int64_t base : {int64_t{-1} << 16, int64_t{0}, int64_t{1} << 16, int64_t{255} << 16, int64_t{256} << 16})
    for (int64_t d : {-32769, -32768, -32767, -1, 0, 1, 32767, 32768, 32769}) values.push_back(static_cast<int32_t>(base + d));
  for (int32_t c : values) {
    for (int ch = 0; ch < 4; ++ch) cv[1].c[ch] = ch == 2 ? c : 0;
    htx::fw::TriangleRecord rec;
    ASSERT_EQ(htx::render::encode_triangle_fx(fmt, pv, {}, &rec), htx::fw::kEncodeOk);
    const int64_t r = (int64_t{c} + 32768) >> 16;  // floor(c / 2^16 + 1/2)
    const uint32_t want = r < 0 ? 0u : (r > 255 ? 255u : static_cast<uint32_t>(r));
    EXPECT_EQ((rec.v[1].rgba >> 16) & 0xFFu, want) << c;
    EXPECT_EQ(rec.v[1].rgba & 0xFF00FFFFu, 0u) << c;
  }
}

// The whole pipeline on the built-in scenes against prepare_screen_scene + the double encoder.
void compare_scene(const char* name) {
  const htx::Scene scene = htx::make_builtin_scene(name);
  const int width = 320, height = 240;
  const htx::ScreenScene ref = htx::prepare_screen_scene(scene, width, height);
  const htx::test::RenderScene rs = htx::test::to_render_scene(scene, width, height);
  const htx::fw::RecordFormat fmt{16, 24, 32, 16};
  htx::render::DrawStats st;
  const std::vector<htx::test::CapturedTriangle> got = htx::test::draw_scene(rs, fmt, 0x1F, &st);
  ASSERT_EQ(got.size(), ref.tris.size());
  EXPECT_GE(got.size(), 6u);
  for (size_t i = 0; i < got.size(); ++i) {
    htx::fw::VertexIn in[3];
    for (int k = 0; k < 3; ++k) {
      const htx::ScreenVertex& v = ref.tris[i].v[static_cast<size_t>(k)];
      in[k] = {v.x, v.y, v.z, v.w, v.u, v.v, v.r, v.g, v.b, v.a};
    }
    htx::fw::TriangleRecord r;
    ASSERT_EQ(htx::fw::encode_triangle(fmt, in, &r), htx::fw::kEncodeOk);
    const htx::fw::TriangleRecord& g = got[i].record;
    for (int k = 0; k < 3; ++k) {
      // Vertices within 1/8 pixel: the Q16.16 scene and matrices against doubles.
      EXPECT_LE(std::abs(g.v[k].x - r.v[k].x), 32) << name << " tri " << i;
      EXPECT_LE(std::abs(g.v[k].y - r.v[k].y), 32) << name << " tri " << i;
      // Depth within 2^-12, q within 2^-12 relative (24-bit z, 32-bit q).
      EXPECT_LE(std::fabs(static_cast<double>(g.v[k].z) - r.v[k].z), 4096.0) << name << " tri " << i;
      const double gq = std::ldexp(static_cast<double>(g.v[k].q), -(g.q_exp + 32));
      const double rq = std::ldexp(static_cast<double>(r.v[k].q), -(r.q_exp + 32));
      EXPECT_NEAR(gq / rq, 1.0, 1.0 / 4096) << name << " tri " << i;
      // Texel coordinate u = uq / q + offset within 1/64 texel.
      const double gu = static_cast<double>(g.v[k].uq) / g.v[k].q + g.u_offset;
      const double ru = static_cast<double>(r.v[k].uq) / r.v[k].q + r.u_offset;
      EXPECT_NEAR(gu, ru, 1.0 / 64) << name << " tri " << i;
      EXPECT_EQ(g.v[k].rgba, r.v[k].rgba);
    }
  }
}

TEST(RenderPipeline, CubeMatchesTheDoubleGeometryStage) { compare_scene("cube"); }
TEST(RenderPipeline, FloorMatchesTheDoubleGeometryStage) { compare_scene("floor"); }

}  // namespace
