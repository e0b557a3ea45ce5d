// AUTO's error bounds (firmware/lib auto_select.h, docs/auto.md) against the true errors of the
// interpolation schemes they bound, computed in doubles on random triangles, and the choice rule
// (cheapest within the tolerance; the documented fallback).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "htx/fw/auto_select.h"
#include "htx/render/auto_method.h"

namespace {

using htx::fw::AutoBounds;
using htx::fw::AutoConfig;
using htx::fw::AutoTriangle;

// Perspective-correct u, v at screen point (px, py) from barycentrics of the screen triangle.
struct Persp {
  const AutoTriangle& t;
  double det;
  explicit Persp(const AutoTriangle& tri)
      : t(tri), det((tri.x[1] - tri.x[0]) * (tri.y[2] - tri.y[0]) - (tri.x[2] - tri.x[0]) * (tri.y[1] - tri.y[0])) {}
  void bary(double px, double py, double l[3]) const {
    l[1] = ((px - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (py - t.y[0])) / det;
    l[2] = ((t.x[1] - t.x[0]) * (py - t.y[0]) - (px - t.x[0]) * (t.y[1] - t.y[0])) / det;
    l[0] = 1 - l[1] - l[2];
  }
  // Exact (perspective) value of axis a at a screen point.
  double exact(const float a[3], double px, double py) const {
    double l[3], num = 0, den = 0;
    bary(px, py, l);
    for (int i = 0; i < 3; ++i) {
      num += l[i] * a[i] / t.w[i];
      den += l[i] / t.w[i];
    }
    return num / den;
  }
  double affine(const float a[3], double px, double py) const {
    double l[3];
    bary(px, py, l);
    return l[0] * a[0] + l[1] * a[1] + l[2] * a[2];
  }
  bool inside(double px, double py) const {
    double l[3];
    bary(px, py, l);
    return l[0] >= 0 && l[1] >= 0 && l[2] >= 0;
  }
};

AutoTriangle random_triangle(std::mt19937& rng) {
  std::uniform_real_distribution<float> pos(0, 200), logr(0, 4), texel(-300, 300), scale(0, 1);
  AutoTriangle t;
  const float s = std::pow(10.0f, -2 * scale(rng));  // texel spans from 300 down to 3
  const float r = std::pow(10.0f, logr(rng) * scale(rng));
  for (int i = 0; i < 3; ++i) {
    t.x[i] = pos(rng);
    t.y[i] = pos(rng);
    t.u[i] = texel(rng) * s;
    t.v[i] = texel(rng) * s;
    t.w[i] = 1 + (r - 1) * scale(rng);
  }
  const unsigned near = rng() % 3, far = (near + 1 + rng() % 2) % 3;  // the extremes of w at two vertices
  t.w[near] = 1;
  t.w[far] = r;
  return t;
}

// Largest error over both axes of a SUBDIV-like scheme in exact arithmetic: per pixel row, exact
// values at the span's first pixel, every n pixels, and its last pixel, linear in between.
double subdiv_true_error(const AutoTriangle& t, unsigned n) {
  const Persp p(t);
  const float* axes[2] = {t.u, t.v};
  double worst = 0;
  const int y0 = static_cast<int>(std::floor(std::min({t.y[0], t.y[1], t.y[2]})));
  const int y1 = static_cast<int>(std::ceil(std::max({t.y[0], t.y[1], t.y[2]})));
  const int x0 = static_cast<int>(std::floor(std::min({t.x[0], t.x[1], t.x[2]})));
  const int x1 = static_cast<int>(std::ceil(std::max({t.x[0], t.x[1], t.x[2]})));
  for (int y = y0; y <= y1; ++y) {
    const double py = y + 0.5;
    int first = -1, last = -1;
    for (int x = x0; x <= x1; ++x)
      if (p.inside(x + 0.5, py)) {
        if (first < 0) first = x;
        last = x;
      }
    if (first < 0) continue;
    for (const float* a : axes)
      for (int s = first; s < last; s += static_cast<int>(n)) {
        const int e = std::min(last, s + static_cast<int>(n));
        const double ua = p.exact(a, s + 0.5, py), ub = p.exact(a, e + 0.5, py);
        for (int x = s; x <= e; ++x) {
          const double lin = ua + (ub - ua) * (x - s) / static_cast<double>(e - s);
          worst = std::max(worst, std::fabs(lin - p.exact(a, x + 0.5, py)));
        }
      }
  }
  return worst;
}

double affine_true_error(const AutoTriangle& t) {
  const Persp p(t);
  double worst = 0;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; i + j <= 60; ++j) {
      const double l1 = i / 60.0, l2 = j / 60.0, l0 = 1 - l1 - l2;
      const double px = l0 * t.x[0] + l1 * t.x[1] + l2 * t.x[2], py = l0 * t.y[0] + l1 * t.y[1] + l2 * t.y[2];
      worst = std::max(worst, std::fabs(p.exact(t.u, px, py) - p.affine(t.u, px, py)));
      worst = std::max(worst, std::fabs(p.exact(t.v, px, py) - p.affine(t.v, px, py)));
    }
  return worst;
}

TEST(AutoBounds, AffineAndSubdivBoundsHoldOnRandomTriangles) {
  std::mt19937 rng(2026);
  const AutoConfig cfg = htx::fw::kAutoConfigIcebreaker;
  int tight_affine = 0, tight_subdiv = 0, checked = 0;
  for (int k = 0; k < 300; ++k) {
    const AutoTriangle t = random_triangle(rng);
    const double det = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
    if (std::fabs(det) < 50) continue;
    ++checked;
    const AutoBounds b = htx::fw::auto_bounds(t, cfg, {});
    const double aff = affine_true_error(t);
    ASSERT_LE(aff, b.affine) << "triangle " << k;
    tight_affine += aff > 0.5 * b.affine;
    for (const unsigned n : {4u, 16u, 64u}) {
      const double sub = subdiv_true_error(t, n);
      ASSERT_LE(sub, htx::fw::auto_bound_subdiv(b, cfg, n)) << "triangle " << k << " n " << n;
      tight_subdiv += sub > 0.1 * htx::fw::auto_bound_subdiv(b, cfg, n);
    }
  }
  EXPECT_GT(checked, 200);
  // The bounds are not vacuous: the affine one is within 2x of the truth on most triangles, and the
  // SUBDIV one within 10x on a good share (it takes the extremes of slope and 1/q jointly).
  EXPECT_GT(tight_affine, checked / 2);
  EXPECT_GT(tight_subdiv, checked / 4);
}

TEST(AutoChoose, CheapestWithinToleranceAmongEveryCandidate) {
  std::mt19937 rng(77);
  AutoConfig always_choose = htx::fw::kAutoConfigIcebreaker;
  always_choose.choice_cycles = 0;
  for (const AutoConfig& cfg : {htx::fw::kAutoConfigIcebreaker, always_choose, htx::fw::kAutoConfigFull}) {
    int per_method[5] = {}, skipped = 0;
    for (int k = 0; k < 2000; ++k) {
      const AutoTriangle t = random_triangle(rng);
      const float tol = (k % 3 == 0) ? 1.0f / 64 : (k % 3 == 1 ? 1.0f / 16 : 0.5f);
      const htx::fw::AutoSampling s{1, 6};
      const htx::fw::AutoChoice c = htx::fw::choose_method(t, cfg, s, 0x1F, tol);
      ASSERT_LT(c.method, 5);
      ++per_method[c.method];
      if (!c.within) {
        EXPECT_EQ(c.method, htx::fw::kAutoRecipNr);
        continue;
      }
      EXPECT_LE(c.bound, tol);
      // No candidate within the tolerance is cheaper; where the choice was skipped, none is
      // cheaper by as much as choosing costs.
      if (c.skipped) {
        EXPECT_EQ(c.method, htx::fw::kAutoRecipNr);
        ++skipped;
      }
      const auto not_cheaper = [&](float cost) {
        return c.skipped ? cost + float(cfg.choice_cycles) > c.cycles : cost >= c.cycles;
      };
      const AutoBounds b = htx::fw::auto_bounds(t, cfg, s);
      const float plain[5] = {b.affine, 0, b.recip_lut, b.recip_nr, b.divfree};
      for (uint8_t m : {0, 2, 3, 4})
        if (plain[m] <= tol) {
          EXPECT_TRUE(not_cheaper(htx::fw::auto_cycles(t, cfg, m, 0))) << "method " << int(m);
        }
      for (unsigned n = 2; n <= 64; ++n)
        if (htx::fw::auto_bound_subdiv(b, cfg, n) <= tol) {
          EXPECT_TRUE(not_cheaper(htx::fw::auto_cycles(t, cfg, htx::fw::kAutoSubdiv, n))) << "subdiv " << n;
        }
    }
    // Only a configuration that prices the choice skips it, and then not always.
    if (cfg.choice_cycles == 0) {
      EXPECT_EQ(skipped, 0);
    } else {
      EXPECT_GT(skipped, 100);
      EXPECT_LT(skipped, 1900);
    }
    // Every method of the choice is exercised by these triangles, except DIVFREE (half a cell).
    if (cfg.recip_issue_interval > 1) {
      EXPECT_GT(per_method[htx::fw::kAutoAffine], 0);
      EXPECT_GT(per_method[htx::fw::kAutoSubdiv], 0);
      EXPECT_GT(per_method[htx::fw::kAutoRecipLut], 0);
      EXPECT_GT(per_method[htx::fw::kAutoRecipNr], 0);
    } else {
      // A pipelined divider makes RECIP_NR as cheap as AFFINE and more accurate.
      EXPECT_EQ(per_method[htx::fw::kAutoRecipNr], 2000);
    }
  }
}

// A triangle whose every method saves the raster unit fewer clocks than choosing costs the CPU gets
// RECIP_NR without comparing, when RECIP_NR is built and within the tolerance (docs/auto.md, "When
// choosing does not pay").
TEST(AutoChoose, RecipNrWithoutComparingWhereChoosingCannotPay) {
  const AutoConfig cfg = htx::fw::kAutoConfigIcebreaker;
  AutoConfig free_choice = cfg;
  free_choice.choice_cycles = 0;
  // 12 x 10 pixels (60) in perspective: at most 11.25 clocks a pixel to save, 675 < 4,500.
  const AutoTriangle small{{10, 22, 10}, {10, 10, 20}, {1, 1.5f, 1.2f}, {0, 8, 0}, {0, 0, 8}};
  htx::fw::AutoChoice c = htx::fw::choose_method(small, cfg, {}, 0x1F, 1.0f / 16);
  EXPECT_TRUE(c.skipped);
  EXPECT_TRUE(c.within);
  EXPECT_EQ(c.method, htx::fw::kAutoRecipNr);
  EXPECT_EQ(c.bound, htx::fw::auto_bounds(small, cfg, {}).recip_nr);
  EXPECT_EQ(c.cycles, htx::fw::auto_cycles(small, cfg, htx::fw::kAutoRecipNr, 0));
  // Priced as free, the choice is a cheaper method (RECIP_LUT's table is within 1/16 here), and the
  // clocks it saves are below what the choice costs.
  const htx::fw::AutoChoice chosen = htx::fw::choose_method(small, free_choice, {}, 0x1F, 1.0f / 16);
  EXPECT_FALSE(chosen.skipped);
  EXPECT_NE(chosen.method, htx::fw::kAutoRecipNr);
  EXPECT_LT(chosen.cycles, c.cycles);
  EXPECT_LT(c.cycles - chosen.cycles, float(cfg.choice_cycles));
  // Not skipped: a triangle large enough to save more (2,000 pixels), RECIP_NR not built, and a
  // tolerance RECIP_NR's bound exceeds (the chooser then compares and falls back).
  const AutoTriangle large{{10, 110, 10}, {10, 10, 50}, {1, 1.5f, 1.2f}, {0, 8, 0}, {0, 0, 8}};
  EXPECT_FALSE(htx::fw::choose_method(large, cfg, {}, 0x1F, 1.0f / 16).skipped);
  c = htx::fw::choose_method(small, cfg, {}, 0x17, 1.0f / 16);
  EXPECT_FALSE(c.skipped);
  EXPECT_EQ(c.method, chosen.method);
  c = htx::fw::choose_method(small, cfg, {}, 0x1F, htx::fw::auto_bounds(small, cfg, {}).recip_nr * 0.99f);
  EXPECT_FALSE(c.skipped);
}

// x with a x = 1 modulo m, for a and m coprime (extended Euclid).
int64_t inverse_mod(int64_t a, int64_t m) {
  int64_t r0 = m, r1 = a, t0 = 0, t1 = 1;
  while (r1 != 0) {
    const int64_t q = r0 / r1;
    r0 -= q * r1, std::swap(r0, r1);
    t0 -= q * t1, std::swap(t0, t1);
  }
  return (t0 % m + m) % m;
}

// The firmware tests the skip in integers before any AutoNum work (render::auto_mesh, auto_method):
// over random fixed-point triangles its choice is the chooser's, bit for bit. A fifth are random
// anywhere; a fifth have an area within 2 % of the skip's limit (400 pixels on icebreaker); a
// fifth one within 120 units (2^-16 pixel) of it; a fifth a texel span within 2^-8 of the
// integer test's limit at tolerances just above RECIP_NR's rounding; a fifth are slivers whose
// determinant AutoNum truncates, within 2,000 units of the limit. Both sides of each margin are
// reached: some triangles the integer test leaves to the chooser are skipped there.
TEST(AutoChoose, FirmwareSkipTestAgreesWithTheChooser) {
  std::mt19937 rng(4242);
  enum Kind { kAnywhere, kNearArea, kAtArea, kAtSpan, kThinAtArea };
  int integer_skips[5] = {}, chooser_skips[5] = {}, compared[5] = {};
  htx::render::ClipVert cv[3] = {};
  htx::render::ScreenVert sv[3] = {};
  const htx::render::ScreenVert* pv[3] = {&sv[0], &sv[1], &sv[2]};
  for (int k = 0; k < 75000; ++k) {
    const Kind kind = static_cast<Kind>(k % 5);
    const bool full = kind == kAnywhere && k % 8 == 4;
    const AutoConfig cfg = full ? htx::fw::kAutoConfigFull : htx::fw::kAutoConfigIcebreaker;
    const htx::render::TexSize tex{static_cast<uint8_t>(rng() % 9), static_cast<uint8_t>(rng() % 9)};
    const htx::fw::AutoSampling s{static_cast<uint8_t>(rng() % 3),
                                  static_cast<uint8_t>(std::max(tex.log2_width, tex.log2_height))};
    // (an untextured mesh's tolerance, 2^40 in Q16.16, now and then among the random ones)
    const int64_t tol_q16 = kind == kAtSpan                   ? 257 + static_cast<int64_t>(rng() % 64)
                            : kind == kAnywhere && k % 7 == 0 ? int64_t{1} << 40
                            : kind == kAnywhere && k % 3 == 0 ? int64_t{1} << (rng() % 17)
                                                              : 4096;
    const uint32_t built = kind == kAnywhere && rng() % 4 == 0 ? static_cast<uint32_t>(rng() % 32) : 0x1Fu;
    const htx::render::AutoMesh mesh = htx::render::auto_mesh(cfg, s, tex, htx::render::auto_tolerance(tol_q16), built);

    const int32_t x0 = static_cast<int32_t>(rng() % (640 * 256)), y0 = static_cast<int32_t>(rng() % (480 * 256));
    int32_t xs[3] = {x0, x0, x0}, ys[3] = {y0, y0, y0};
    if (kind == kAnywhere) {
      const int extent = 1 << (rng() % 12);
      for (int i = 0; i < 3; ++i) {
        xs[i] += static_cast<int32_t>(rng() % (extent * 256)) - extent * 128;
        ys[i] += static_cast<int32_t>(rng() % (extent * 256)) - extent * 128;
      }
    } else if (kind == kNearArea) {
      const double leg = 8 + (rng() % 10000) / 100.0, area = 400 * (0.98 + (rng() % 4001) / 100000.0);
      xs[1] += int32_t(leg * 256);
      ys[2] += int32_t(2 * area / leg * 256);
    } else if (kind == kAtArea) {
      // Twice the area dx * dy - off * 1: 0 to 119 units below 52,428,800 (400 pixels); the
      // integer test's slack is about fifty units here.
      const int32_t dx = int32_t{1} << (10 + rng() % 4);
      xs[1] += dx, ys[1] += 1, xs[2] += static_cast<int32_t>(rng() % 120), ys[2] += 52428800 / dx;
    } else if (kind == kThinAtArea) {
      // A sliver 2,048 to 3,072 pixels long whose determinant A D - C B is exactly 52,428,800 - r,
      // r < 2,000 (A, C odd and coprime; D from A's inverse modulo C, then B), in either
      // orientation. Its two products lie near 2^39, which AutoNum truncates by up to some 2^9
      // units either way, so the slack (about 2^20 here) is what keeps the integer test from
      // skipping where the chooser does not.
      int64_t a = 0, c = 0;
      do {
        a = (int64_t{1} << 19) + 2 * static_cast<int64_t>(rng() % (1u << 17)) + 1;
        c = (int64_t{1} << 19) + 2 * static_cast<int64_t>(rng() % (1u << 17)) + 1;
      } while (std::gcd(a, c) != 1);
      const int64_t target = 52428800 - static_cast<int64_t>(rng() % 2000);
      const int64_t d = (int64_t{1} << 19) + ((target % c) * inverse_mod(a % c, c) % c - (int64_t{1} << 19) % c + 2 * c) % c;
      const int64_t b = (a * d - target) / c;
      const int first = k % 2 == 0 ? 1 : 2, second = 3 - first;
      xs[first] += static_cast<int32_t>(a), ys[first] += static_cast<int32_t>(b);
      xs[second] += static_cast<int32_t>(c), ys[second] += static_cast<int32_t>(d);
      const int64_t det = (int64_t{xs[1]} - xs[0]) * (ys[2] - ys[0]) - (int64_t{xs[2]} - xs[0]) * (ys[1] - ys[0]);
      ASSERT_EQ(det < 0 ? -det : det, target) << "triangle " << k;
    } else {
      xs[1] += 10 * 256, ys[2] += 10 * 256;  // 50 pixels
    }
    const int span_bits = 1 + static_cast<int>(rng() % (kind == kAnywhere ? 26 : 12));
    for (int i = 0; i < 3; ++i) {
      cv[i].s = static_cast<int32_t>(rng() % (1u << span_bits)) - (1 << 20);
      cv[i].t = static_cast<int32_t>(rng() % (1u << span_bits)) - (1 << 20);
      sv[i].x = xs[i];
      sv[i].y = ys[i];
      sv[i].w = 1 + static_cast<int32_t>(rng() % (1u << (8 + rng() % 22)));
      sv[i].attr = &cv[i];
    }
    if (kind == kAtSpan && mesh.skip_s_range > 0) {
      // s spans the integer limit times 1 +- 2^-8 (t a tenth of its own limit).
      const double f = 1 + (static_cast<double>(rng() % 2001) - 1000) / 1000 / 256;
      cv[1].s = cv[0].s + static_cast<int32_t>(std::min<double>(double(mesh.skip_s_range) * f, 1 << 30));
      cv[2].s = cv[0].s + (cv[1].s - cv[0].s) / 2;
      cv[1].t = cv[0].t + static_cast<int32_t>(std::min<int64_t>(mesh.skip_t_range / 10, 1 << 30));
      cv[2].t = cv[0].t;
    }
    const htx::fw::AutoChoice got = htx::render::auto_method(pv, mesh);
    const htx::fw::AutoChoice want =
        htx::fw::choose_method(htx::render::auto_triangle(pv, tex), mesh.pricing, s, built, mesh.tolerance);
    ASSERT_EQ(got.method, want.method) << "triangle " << k;
    ASSERT_EQ(got.subdiv_n, want.subdiv_n) << "triangle " << k;
    ASSERT_EQ(got.within, want.within) << "triangle " << k;
    ASSERT_EQ(got.skipped, want.skipped) << "triangle " << k;
    if (got.skipped && got.bound == 0) ++integer_skips[kind];  // (the chooser reports a bound > 0)
    else if (got.skipped) ++chooser_skips[kind];
    else ++compared[kind];
  }
  for (const Kind kind : {kAnywhere, kNearArea, kAtArea, kAtSpan, kThinAtArea})
    std::printf("kind %d: %d skipped in integers, %d by the chooser, %d compared\n", kind, integer_skips[kind],
                chooser_skips[kind], compared[kind]);
  // Both sides of each margin. Every kind has triangles the integer test skips, except the slivers:
  // their determinant is under 2,000 units below the limit, far inside the integer test's slack
  // (about 2^20 units there), so it leaves every one of them to the chooser.
  EXPECT_GT(integer_skips[kAnywhere], 1000);
  EXPECT_GT(integer_skips[kNearArea], 1000);
  EXPECT_GT(integer_skips[kAtArea], 1000);
  EXPECT_GT(integer_skips[kAtSpan], 1000);
  EXPECT_EQ(integer_skips[kThinAtArea], 0);
  // Every kind has triangles the chooser compares (few of those at the area's limit: most of them
  // are skipped by one test or the other).
  EXPECT_GT(compared[kAnywhere], 100);
  EXPECT_GT(compared[kNearArea], 100);
  EXPECT_GT(compared[kAtArea], 50);
  EXPECT_GT(compared[kAtSpan], 100);
  EXPECT_GT(compared[kThinAtArea], 1000);
  // Triangles the integer test leaves and the chooser then skips lie within the integer test's
  // slack: at the area's limit, at the span's, and the slivers. (Random triangles and those within
  // 2 % of the area's limit almost never fall there, 0 and 1 of them with this seed: not counted on.)
  EXPECT_GT(chooser_skips[kAtArea], 1000);
  EXPECT_GT(chooser_skips[kAtSpan], 20);
  EXPECT_GT(chooser_skips[kThinAtArea], 1000);
}

// choose_method finds only the bounds that can change its choice (docs/auto.md, "Arithmetic"):
// the same result, bit for bit, as the rule applied literally, over triangles in the firmware's
// fixed-point form (1/256 pixel, Q16.16 w, texel coordinates at several texture sizes), degenerate
// ones and ones without perspective (where methods tie on cost), both configurations, any set of
// built methods, filters and tolerances.
TEST(AutoChoose, EqualsTheRuleAppliedLiterally) {
  std::mt19937_64 rng(2026120516);
  int per_method[5] = {}, subdiv_short = 0;
  for (int k = 0; k < 40000; ++k) {
    htx::fw::AutoTriangleNum t;
    const int extent = 1 << (rng() % 12);  // 1 .. 2048 pixels
    const int tex_log2 = static_cast<int>(rng() % 8);
    const bool degenerate = rng() % 50 == 0;
    const bool flat = rng() % 10 == 0;  // one w for all three (no perspective: AFFINE is exact)
    const int32_t x0 = static_cast<int32_t>(rng() % (320 * 256)), y0 = static_cast<int32_t>(rng() % (240 * 256));
    const int32_t w0 = 1 + static_cast<int32_t>(rng() % (1u << 24));
    for (int i = 0; i < 3; ++i) {
      const auto offset = [&] { return static_cast<int32_t>(rng() % (extent * 256)) - extent * 128; };
      const int32_t x = degenerate ? x0 : x0 + offset();
      const int32_t y = degenerate ? y0 : y0 + offset();
      const int32_t w = flat ? w0 : 1 + static_cast<int32_t>(rng() % (1u << (8 + rng() % 22)));
      const int32_t u = static_cast<int32_t>(rng() % (1u << (1 + rng() % 24))) - 4096;
      const int32_t v = static_cast<int32_t>(rng() % (1u << (1 + rng() % 24))) - 4096;
      t.x[i] = htx::fw::num_scale(htx::fw::num_from_int(x), -8);
      t.y[i] = htx::fw::num_scale(htx::fw::num_from_int(y), -8);
      t.w[i] = htx::fw::num_scale(htx::fw::num_from_int(w), -16);
      t.u[i] = htx::fw::num_scale(htx::fw::num_from_int(u), tex_log2 - 16);
      t.v[i] = htx::fw::num_scale(htx::fw::num_from_int(v), tex_log2 - 16);
    }
    const AutoConfig& cfg = k % 2 ? htx::fw::kAutoConfigFull : htx::fw::kAutoConfigIcebreaker;
    const htx::fw::AutoSampling s{static_cast<uint8_t>(rng() % 3), static_cast<uint8_t>(tex_log2)};
    const uint32_t built = rng() % 4 == 0 ? static_cast<uint32_t>(rng() % 32) : 0x1Fu;
    const htx::fw::AutoNum tol =
        htx::fw::num_scale(htx::fw::num_from_int(1 + static_cast<int32_t>(rng() % 65536)), -16 - static_cast<int>(rng() % 8));
    const htx::fw::AutoChoice want = htx::fw::choose_method_exhaustive(t, cfg, s, built, tol);
    const htx::fw::AutoChoice got = htx::fw::choose_method(t, cfg, s, built, tol);
    ASSERT_EQ(got.method, want.method) << "triangle " << k;
    if (want.method == htx::fw::kAutoSubdiv) {
      ASSERT_EQ(got.subdiv_n, want.subdiv_n) << "triangle " << k;
    }
    ASSERT_EQ(got.within, want.within) << "triangle " << k;
    ASSERT_EQ(got.skipped, want.skipped) << "triangle " << k;
    ASSERT_EQ(got.bound, want.bound) << "triangle " << k;    // both rounded up from the same AutoNum
    ASSERT_EQ(got.cycles, want.cycles) << "triangle " << k;
    ++per_method[want.method];
    subdiv_short += want.method == htx::fw::kAutoSubdiv && want.within && want.subdiv_n < 64;
  }
  // Every method is chosen somewhere, and SUBDIV's search runs (a span below 64).
  for (int m = 0; m < 5; ++m) EXPECT_GT(per_method[m], 0) << "method " << m;
  EXPECT_GT(subdiv_short, 0);
}

TEST(AutoChoose, FallbackAndBadInput) {
  AutoTriangle t{{0, 100, 0}, {0, 0, 100}, {1, 4, 2}, {0, 200, 0}, {0, 0, 200}};
  const AutoConfig cfg = htx::fw::kAutoConfigIcebreaker;
  htx::fw::AutoChoice c = htx::fw::choose_method(t, cfg, {}, 0x1F, 1e-9f);
  EXPECT_FALSE(c.within);
  EXPECT_EQ(c.method, htx::fw::kAutoRecipNr);
  c = htx::fw::choose_method(t, cfg, {}, 0x17, 1e-9f);  // no RECIP_NR
  EXPECT_EQ(c.method, htx::fw::kAutoRecipLut);
  c = htx::fw::choose_method(t, cfg, {}, 0x13, 1e-9f);  // no divider at all but SUBDIV
  EXPECT_EQ(c.method, htx::fw::kAutoSubdiv);
  EXPECT_EQ(c.subdiv_n, 2);
  c = htx::fw::choose_method(t, cfg, {}, 0x1F, 1e6f);  // anything goes: the cheapest of all
  EXPECT_TRUE(c.within);
  for (uint8_t m : {0, 2, 3, 4}) EXPECT_LE(c.cycles, htx::fw::auto_cycles(t, cfg, m, 0)) << "method " << int(m);
  for (unsigned n = 2; n <= 64; ++n) EXPECT_LE(c.cycles, htx::fw::auto_cycles(t, cfg, htx::fw::kAutoSubdiv, n));
  // On icebreaker's RTL SUBDIV's exact points at the longest span hide behind the traversal's steps,
  // and it needs neither AFFINE's vertex divisions nor DIVFREE's seed division (docs/auto.md).
  EXPECT_EQ(c.method, htx::fw::kAutoSubdiv);
  EXPECT_EQ(c.subdiv_n, 64);
  t.w[1] = NAN;
  c = htx::fw::choose_method(t, cfg, {}, 0x1F, 1.0f);
  EXPECT_FALSE(c.within);
  EXPECT_EQ(c.method, htx::fw::kAutoRecipNr);
  t.w[1] = -1;
  EXPECT_FALSE(htx::fw::choose_method(t, cfg, {}, 0x1F, 1.0f).within);
  t.w[1] = 4;
  EXPECT_FALSE(htx::fw::choose_method(t, cfg, {}, 0x1F, 0.0f).within);  // tolerance must be > 0
  // A degenerate triangle (zero area, its w varying along it): SUBDIV's slope and curvature terms,
  // which divide by the determinant, are taken as 0 instead, so with SUBDIV alone built it is
  // within a 1/16-texel tolerance at its longest span. (Divided by the zero determinant, for which
  // AutoNum's division gives 2^50, they would be huge: nothing within, and the fallback SUBDIV_2
  // with within = false.)
  const AutoTriangle line{{0, 10, 20}, {0, 10, 20}, {1, 2, 3}, {0, 5, 9}, {0, 1, 2}};
  c = htx::fw::choose_method(line, cfg, {}, 1u << htx::fw::kAutoSubdiv, 1.0f / 16);
  EXPECT_EQ(c.method, htx::fw::kAutoSubdiv);
  EXPECT_TRUE(c.within);
  EXPECT_EQ(c.subdiv_n, 64);
  EXPECT_GT(c.bound, 0.0f);
  EXPECT_LT(c.bound, 1.0f / 16);
}

TEST(AutoChoose, FirmwareAdapterSeesPixelsAndTexels) {
  htx::render::ClipVert cv[3] = {};
  htx::render::ScreenVert sv[3] = {};
  const int32_t xs[3] = {0, 100, 0}, ys[3] = {0, 0, 100};
  for (int i = 0; i < 3; ++i) {
    cv[i].s = i == 1 ? 65536 : 0;  // s = 1.0: one texture width
    cv[i].t = i == 2 ? 32768 : 0;
    sv[i].x = xs[i] * 256;
    sv[i].y = ys[i] * 256;
    sv[i].w = 65536 * (i + 1);
    sv[i].attr = &cv[i];
  }
  const htx::render::ScreenVert* pv[3] = {&sv[0], &sv[1], &sv[2]};
  const htx::fw::AutoTriangleNum tn = htx::render::auto_triangle(pv, {6, 5});
  EXPECT_EQ(htx::fw::num_to_float_up(tn.x[1]), 100.0f);
  EXPECT_EQ(htx::fw::num_to_float_up(tn.y[2]), 100.0f);
  EXPECT_EQ(htx::fw::num_to_float_up(tn.w[2]), 3.0f);
  EXPECT_EQ(htx::fw::num_to_float_up(tn.u[1]), 64.0f);
  EXPECT_EQ(htx::fw::num_to_float_up(tn.v[2]), 16.0f);
  AutoTriangle t{};
  for (int i = 0; i < 3; ++i) {
    t.x[i] = htx::fw::num_to_float_up(tn.x[i]);
    t.y[i] = htx::fw::num_to_float_up(tn.y[i]);
    t.w[i] = htx::fw::num_to_float_up(tn.w[i]);
    t.u[i] = htx::fw::num_to_float_up(tn.u[i]);
    t.v[i] = htx::fw::num_to_float_up(tn.v[i]);
  }
  const htx::fw::AutoChoice c = htx::render::auto_method(
      pv, htx::render::auto_mesh(htx::fw::kAutoConfigIcebreaker, {}, {6, 5}, htx::render::auto_tolerance(4096), 0x1F));
  EXPECT_EQ(c.method, htx::fw::choose_method(t, htx::fw::kAutoConfigIcebreaker, {}, 0x1F, 1.0f / 16).method);
}

}  // namespace
