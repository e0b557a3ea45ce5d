#include "htx/fw/auto_select.h"

namespace htx::fw {

namespace {

float absf(float x) { return x < 0 ? -x : x; }
float maxf(float a, float b) { return a > b ? a : b; }
float minf(float a, float b) { return a < b ? a : b; }
bool finitef(float x) { return x == x && x < 3.0e38f && x > -3.0e38f; }

// 2^e for -126 <= e <= 127, built from its exponent bits (exact; no libm, no loop: this runs per
// triangle on a CPU without floating point).
float pow2f(int e) {
  const uint32_t bits = static_cast<uint32_t>(e + 127) << 23;
  float r;
  __builtin_memcpy(&r, &bits, sizeof r);
  return r;
}

// sqrt(x) for x >= 1: a first guess from halving the exponent (within a factor of 1.5), then
// Newton's method, which from the second step on decreases monotonically; it stops when it no
// longer does (float precision), at most 8 steps.
float sqrt_ge1(float x) {
  uint32_t bits;
  __builtin_memcpy(&bits, &x, sizeof bits);
  const uint32_t guess_bits = ((bits >> 23) - 127) / 2 + 127;
  float y;
  const uint32_t g = guess_bits << 23;
  __builtin_memcpy(&y, &g, sizeof y);
  y = 0.5f * (y + x / y);
  for (int i = 0; i < 8; ++i) {
    const float next = 0.5f * (y + x / y);
    if (!(next < y)) break;
    y = next;
  }
  return y;
}

// Rounding of the TF-bit texel coordinates and of the plane arithmetic, common to every method
// (docs/auto.md: 4 ulps of TF; icebreaker's measured RECIP_NR error, 0.0027 texel, is within it).
float base_error(const AutoConfig& c) { return pow2f(2 - c.texcoord_frac_bits); }

// Relative error of the reciprocal table alone and after the pixel Newton steps (docs/model.md §4, §5).
float table_error(const AutoConfig& c) {
  return pow2f(-(c.recip_table_bits + 1)) * (1.0f + pow2f(-(c.recip_guard_bits + 1)));
}
float newton_error(const AutoConfig& c) {
  float e = table_error(c);
  for (int i = 0; i < c.pixel_nr_steps; ++i) e = e * e + pow2f(2 - c.recip_width);
  return e;
}

struct Extent {
  float x_lo, x_hi, y_lo, y_hi, w_lo, w_hi;
};

Extent extent_of(const AutoTriangle& t) {
  Extent e{t.x[0], t.x[0], t.y[0], t.y[0], t.w[0], t.w[0]};
  for (int i = 1; i < 3; ++i) {
    e.x_lo = minf(e.x_lo, t.x[i]);
    e.x_hi = maxf(e.x_hi, t.x[i]);
    e.y_lo = minf(e.y_lo, t.y[i]);
    e.y_hi = maxf(e.y_hi, t.y[i]);
    e.w_lo = minf(e.w_lo, t.w[i]);
    e.w_hi = maxf(e.w_hi, t.w[i]);
  }
  return e;
}

float range_of(const float a[3]) {
  return maxf(a[0], maxf(a[1], a[2])) - minf(a[0], minf(a[1], a[2]));
}

// Slope and curvature of one texture axis a along screen x (docs/auto.md, "SUBDIV"): with the
// planes Q = q and A = (a - c) q, da/dx = k / Q^2 where k = gA*Q - A*gQ is constant along x (so
// its extremes over the triangle are at vertices), and d2a/dx2 = -2 k gQ / Q^3.
void axis_derivatives(const float a[3], const float q[3], const float dy[3], float det, float q_min,
                      float* slope, float* curvature) {
  const float c = 0.5f * (maxf(a[0], maxf(a[1], a[2])) + minf(a[0], minf(a[1], a[2])));
  float A[3];
  for (int i = 0; i < 3; ++i) A[i] = (a[i] - c) * q[i];
  const float g_q = ((q[1] - q[0]) * dy[2] - (q[2] - q[0]) * dy[1]) / det;
  const float g_a = ((A[1] - A[0]) * dy[2] - (A[2] - A[0]) * dy[1]) / det;
  float k_max = 0;
  for (int i = 0; i < 3; ++i) k_max = maxf(k_max, absf(q[i] * g_a - A[i] * g_q));
  const float q2 = q_min * q_min;
  *slope = k_max / q2;
  *curvature = 2.0f * k_max * absf(g_q) / (q2 * q_min);
}

}  // namespace

AutoBounds auto_bounds(const AutoTriangle& t, const AutoConfig& cfg, const AutoSampling& s) {
  const Extent e = extent_of(t);
  AutoBounds b{};
  b.du = maxf(range_of(t.u), range_of(t.v));
  const float base = base_error(cfg);
  const float r = e.w_hi / e.w_lo;
  const float sr = sqrt_ge1(r);
  b.affine = b.du * (sr - 1.0f) / (sr + 1.0f) + base;
  const float local = 0.5f * b.du + 1.0f;  // |u - u_offset| (the offset is the rounded midpoint)
  b.recip_lut = local * table_error(cfg) + base;
  b.recip_nr = local * newton_error(cfg) + base;
  b.divfree = (s.filter == 0 ? 0.5f : pow2f(s.top_level - cfg.divfree_frac_bits - 1)) + base;
  b.span_limit = e.x_hi - e.x_lo + 1.0f;

  float dx[3], dy[3], q[3];
  for (int i = 0; i < 3; ++i) {
    dx[i] = t.x[i] - t.x[0];
    dy[i] = t.y[i] - t.y[0];
    q[i] = e.w_lo / t.w[i];  // in (0, 1]
  }
  const float det = dx[1] * dy[2] - dx[2] * dy[1];
  const float q_min = e.w_lo / e.w_hi;
  if (det == 0.0f) {
    b.subdiv_slope = b.subdiv_curvature = 0;
    return b;
  }
  float su = 0, cu = 0, sv = 0, cv = 0;
  axis_derivatives(t.u, q, dy, det, q_min, &su, &cu);
  axis_derivatives(t.v, q, dy, det, q_min, &sv, &cv);
  b.subdiv_slope = maxf(su, sv);
  b.subdiv_curvature = maxf(cu, cv);
  return b;
}

float auto_bound_subdiv(const AutoBounds& b, const AutoConfig& cfg, unsigned n) {
  const float l = minf(static_cast<float>(n), b.span_limit);  // pixels between exact points
  const float interp = minf(l * l * 0.125f * b.subdiv_curvature, b.affine);
  const float seg = minf(b.du, l * b.subdiv_slope);  // texels one segment spans
  // The step's 8 extra fraction bits and round(2^16 / L) (docs/model.md §5.3).
  const float step = l * seg * pow2f(-17) + l * pow2f(-9 - cfg.texcoord_frac_bits);
  return interp + step + b.recip_nr;
}

float auto_cycles(const AutoTriangle& t, const AutoConfig& cfg, uint8_t method, unsigned n) {
  const Extent e = extent_of(t);
  const float det = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
  const float pixels = 0.5f * absf(det);
  const float rows = e.y_hi - e.y_lo + 1.0f;
  const float interval = static_cast<float>(cfg.recip_issue_interval);
  const float fixed = 26.0f + 7.0f * interval + rows;  // setup, one clock per span
  // The traversal and the reciprocal unit work side by side: a method takes the longer of the
  // traversal's clocks and the divider's.
  const float traverse = static_cast<float>(cfg.pixel_cost16) / 16.0f * pixels;
  const float nr_divide = static_cast<float>(cfg.nr_divide_cost16) / 16.0f;
  switch (method) {
    case kAutoRecipNr: return fixed + maxf(traverse, nr_divide * pixels);
    case kAutoRecipLut: return fixed + maxf(traverse, static_cast<float>(cfg.lut_divide_cost16) / 16.0f * pixels);
    case kAutoSubdiv: {
      const float points = minf(pixels, pixels / static_cast<float>(n) + 2.0f * rows);
      return fixed + maxf(traverse, nr_divide * points);
    }
    case kAutoDivFree: return fixed + traverse + interval;  // one seed division
    default: return fixed + traverse + static_cast<float>(cfg.affine_setup_cost16) / 16.0f;  // AFFINE
  }
}

AutoChoice choose_method(const AutoTriangle& t, const AutoConfig& cfg, const AutoSampling& s, uint32_t built,
                         float tolerance) {
  AutoChoice best;
  bool ok = tolerance > 0;
  for (int i = 0; i < 3; ++i)
    ok = ok && finitef(t.x[i]) && finitef(t.y[i]) && finitef(t.u[i]) && finitef(t.v[i]) && finitef(t.w[i]) &&
         t.w[i] > 0;
  if (ok) {
    const AutoBounds b = auto_bounds(t, cfg, s);
    const uint8_t plain[4] = {kAutoAffine, kAutoRecipLut, kAutoRecipNr, kAutoDivFree};
    const float bounds[4] = {b.affine, b.recip_lut, b.recip_nr, b.divfree};
    for (int i = 0; i < 4; ++i) {
      if (!(built & (1u << plain[i])) || !(bounds[i] <= tolerance)) continue;
      const float c = auto_cycles(t, cfg, plain[i], 0);
      if (!best.within || c < best.cycles || (c == best.cycles && bounds[i] < best.bound))
        best = AutoChoice{plain[i], 16, true, bounds[i], c};
    }
    // SUBDIV: the longest segment within the tolerance (the bound grows with n, the cost falls, so a
    // binary search over 2..64 finds it), if it is cheaper than the choice so far.
    if ((built & (1u << kAutoSubdiv)) && b.subdiv_curvature == b.subdiv_curvature &&
        auto_bound_subdiv(b, cfg, 2) <= tolerance) {
      unsigned lo = 2, hi = 64;  // bound(lo) within; find the largest such n
      while (lo < hi) {
        const unsigned mid = (lo + hi + 1) / 2;
        if (auto_bound_subdiv(b, cfg, mid) <= tolerance) lo = mid;
        else hi = mid - 1;
      }
      const float c = auto_cycles(t, cfg, kAutoSubdiv, lo);
      if (!best.within || c < best.cycles)
        best = AutoChoice{kAutoSubdiv, static_cast<uint8_t>(lo), true, auto_bound_subdiv(b, cfg, lo), c};
    }
    if (best.within) return best;
  }
  // Nothing predicted within the tolerance: the most accurate divider built.
  best.within = false;
  best.subdiv_n = 16;
  if (built & (1u << kAutoRecipNr)) best.method = kAutoRecipNr;
  else if (built & (1u << kAutoRecipLut)) best.method = kAutoRecipLut;
  else if (built & (1u << kAutoSubdiv)) {
    best.method = kAutoSubdiv;
    best.subdiv_n = 2;
  } else best.method = kAutoAffine;
  if (ok) {
    const AutoBounds b = auto_bounds(t, cfg, s);
    best.bound = best.method == kAutoRecipNr ? b.recip_nr
                 : best.method == kAutoRecipLut ? b.recip_lut
                 : best.method == kAutoSubdiv   ? auto_bound_subdiv(b, cfg, 2)
                                                : b.affine;
    best.cycles = auto_cycles(t, cfg, best.method, best.subdiv_n);
  }
  return best;
}

}  // namespace htx::fw
