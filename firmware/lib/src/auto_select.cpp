#include "htx/fw/auto_select.h"

namespace htx::fw {

namespace {

using Num = AutoNum;
using Tri = AutoTriangleNum;

// Input checks on the float's bits (no soft-float compares): |x| < 3.0e38 and not NaN, and x > 0.
constexpr uint32_t kFiniteLimitBits = 0x7F61B1E6u;  // 3.0e38f
uint32_t bits_of(float x) {
  uint32_t b;
  __builtin_memcpy(&b, &x, sizeof b);
  return b;
}
bool finite_input(float x) { return (bits_of(x) & 0x7FFFFFFFu) < kFiniteLimitBits; }
bool positive_input(float x) { return bits_of(x) != 0 && bits_of(x) <= 0x7F800000u; }

Num num(int32_t v) { return num_from_int(v); }

Tri tri_of(const AutoTriangle& t) {
  Tri n;
  for (int i = 0; i < 3; ++i) {
    n.x[i] = num_from_float(t.x[i]);
    n.y[i] = num_from_float(t.y[i]);
    n.w[i] = num_from_float(t.w[i]);
    n.u[i] = num_from_float(t.u[i]);
    n.v[i] = num_from_float(t.v[i]);
  }
  return n;
}

// sqrt(x) for x >= 1, from above: x = f 4^k with f in [1, 4), a first guess (f + 2) / 3 (within 6 %),
// then two Newton steps. Newton's steps for a square root never end below it, so the result is
// over by at most 2e-6 relative (the error squares each step), which only makes AFFINE's bound
// (increasing in it) safer.
Num sqrt_ge1(Num x) {
  const int32_t exp = x.e + 30;  // x = (m / 2^30) 2^exp, m / 2^30 in [1, 2)
  const int32_t k = exp >> 1;
  const Num f = num_scale(x, -2 * k);
  const Num third = {0x55555556, -32};  // 1/3, rounded up (normalised, as every operand must be)
  Num y = num_scale((f + num(2)) * third, k);
  for (int i = 0; i < 2; ++i) y = num_scale(y + x / y, -1);
  return y;
}

// Rounding of the TF-bit texel coordinates and of the plane arithmetic, common to every method
// (docs/auto.md: 4 ulps of TF; icebreaker's measured RECIP_NR error, 0.0027 texel, is within it).
Num base_error(const AutoConfig& c) { return num_pow2(2 - c.texcoord_frac_bits); }

// Relative error of the reciprocal table alone and after the pixel Newton steps (docs/model.md §4, §5).
Num table_error(const AutoConfig& c) {
  return num_pow2(-(c.recip_table_bits + 1)) * (num(1) + num_pow2(-(c.recip_guard_bits + 1)));
}
Num newton_error(const AutoConfig& c) {
  Num e = table_error(c);
  for (int i = 0; i < c.pixel_nr_steps; ++i) e = e * e + num_pow2(2 - c.recip_width);
  return e;
}

struct Range {
  Num lo, hi;
};
Range range_of(const Num a[3]) {  // three compares, not four
  Range r = a[1] < a[0] ? Range{a[1], a[0]} : Range{a[0], a[1]};
  if (a[2] < r.lo) {
    r.lo = a[2];
  } else if (r.hi < a[2]) {
    r.hi = a[2];
  }
  return r;
}

// What the bounds and the costs share, found once a triangle: the ranges of its coordinates, the
// y edges from vertex 0 and the screen-space determinant (twice the signed area).
struct Shape {
  Range x, y, w, u, v;
  Num dy[3], det;
};
Shape shape_of(const Tri& t) {
  Shape sh{range_of(t.x), range_of(t.y), range_of(t.w), range_of(t.u), range_of(t.v), {}, {}};
  Num dx[3];  // dx[0] and dy[0] are zero (x - x is exactly 0)
  for (int i = 1; i < 3; ++i) {
    dx[i] = t.x[i] - t.x[0];
    sh.dy[i] = t.y[i] - t.y[0];
  }
  sh.det = dx[1] * sh.dy[2] - dx[2] * sh.dy[1];
  return sh;
}

// For one texture axis a with the planes Q = q and A = (a - c) q (c the middle of a's range),
// da/dx = k / Q^2 where k = gA*Q - A*gQ is constant along x, so its extremes over the triangle are
// at the vertices (docs/auto.md, "SUBDIV"): the largest |k| at a vertex. g_q is the q plane's x
// gradient, the same for both axes; inv_det = 1 / the determinant.
Num axis_k_max(const Num a[3], Range range, const Num q[3], const Num dy[3], Num inv_det, Num g_q) {
  const Num c = num_scale(range.hi + range.lo, -1);
  Num A[3];
  for (int i = 0; i < 3; ++i) A[i] = (a[i] - c) * q[i];
  const Num g_a = ((A[1] - A[0]) * dy[2] - (A[2] - A[0]) * dy[1]) * inv_det;
  Num k_max;
  for (int i = 0; i < 3; ++i) k_max = num_max(k_max, num_abs(q[i] * g_a - A[i] * g_q));
  return k_max;
}

struct Bounds {
  Num affine, recip_lut, recip_nr, divfree, subdiv_slope, subdiv_curvature, span_limit, du;
};

// The bounds that take a few operations each: every one but AFFINE's and SUBDIV's terms.
void cheap_bounds(const Shape& sh, const AutoPricing& pr, const AutoSampling& s, Bounds* b) {
  b->du = num_max(sh.u.hi - sh.u.lo, sh.v.hi - sh.v.lo);
  const Num local = num_scale(b->du, -1) + num(1);  // |u - u_offset| (the offset is the rounded midpoint)
  b->recip_lut = local * pr.table_error + pr.base;
  b->recip_nr = local * pr.newton_error + pr.base;
  b->divfree = (s.filter == 0 ? num_pow2(-1) : num_pow2(s.top_level - pr.cfg.divfree_frac_bits - 1)) + pr.base;
  b->span_limit = sh.x.hi - sh.x.lo + num(1);
}

// AFFINE's bound (a square root and two divisions); SUBDIV's interpolation term is capped by it.
Num affine_bound(const Shape& sh, Num du, const AutoPricing& pr) {
  const Num sr = sqrt_ge1(sh.w.hi / sh.w.lo);
  return du * (sr - num(1)) / (sr + num(1)) + pr.base;
}

// SUBDIV's slope k / Q^2 and curvature 2 k gQ / Q^3, largest at the largest |k| of either axis and
// the smallest Q (five divisions and some fifty operations: the chooser's largest part).
void subdiv_terms(const Tri& t, const Shape& sh, Bounds* b) {
  b->subdiv_slope = Num{};
  b->subdiv_curvature = Num{};
  if (sh.det.m == 0) return;  // slope and curvature 0
  Num q[3];
  for (int i = 0; i < 3; ++i) q[i] = sh.w.lo / t.w[i];  // in (0, 1]
  const Num inv_det = num(1) / sh.det;
  const Num q_min = sh.w.lo / sh.w.hi;
  const Num g_q = ((q[1] - q[0]) * sh.dy[2] - (q[2] - q[0]) * sh.dy[1]) * inv_det;
  const Num k_max =
      num_max(axis_k_max(t.u, sh.u, q, sh.dy, inv_det, g_q), axis_k_max(t.v, sh.v, q, sh.dy, inv_det, g_q));
  const Num q2 = q_min * q_min;
  b->subdiv_slope = k_max / q2;
  b->subdiv_curvature = num_scale(b->subdiv_slope * num_abs(g_q), 1) / q_min;
}

Bounds bounds_of(const Tri& t, const Shape& sh, const AutoPricing& pr, const AutoSampling& s) {
  Bounds b;
  cheap_bounds(sh, pr, s, &b);
  b.affine = affine_bound(sh, b.du, pr);
  subdiv_terms(t, sh, &b);
  return b;
}

Num bound_subdiv(const Bounds& b, const AutoPricing& pr, unsigned n) {
  const Num l = num_min(num(static_cast<int32_t>(n)), b.span_limit);  // pixels between exact points
  const Num interp = num_min(num_scale(l * l * b.subdiv_curvature, -3), b.affine);
  const Num seg = num_min(b.du, l * b.subdiv_slope);  // texels one segment spans
  // The step's 8 extra fraction bits and round(2^16 / L) (docs/model.md §5.3).
  const Num step = num_scale(l * seg, -17) + num_scale(l, -9 - pr.cfg.texcoord_frac_bits);
  return interp + step + b.recip_nr;
}

// What every method's cost shares (docs/model.md §9 estimate), computed once a triangle.
struct Footprint {
  Num pixels, rows, fixed, traverse;
};

Footprint footprint_of(const Shape& sh, const AutoPricing& pr) {
  Footprint f;
  f.pixels = num_scale(num_abs(sh.det), -1);
  f.rows = sh.y.hi - sh.y.lo + num(1);
  f.fixed = pr.setup + f.rows;  // setup, one clock per span
  f.traverse = pr.pixel_cost * f.pixels;
  return f;
}

// The traversal and the reciprocal unit work side by side: a method takes the longer of the
// traversal's clocks and the divider's.
Num cycles_of(const Footprint& f, const AutoPricing& pr, uint8_t method, unsigned n) {
  switch (method) {
    case kAutoRecipNr: return f.fixed + num_max(f.traverse, pr.nr_divide * f.pixels);
    case kAutoRecipLut: return f.fixed + num_max(f.traverse, pr.lut_divide * f.pixels);
    case kAutoSubdiv: {
      const Num points = num_min(f.pixels, f.pixels / num(static_cast<int32_t>(n)) + num_scale(f.rows, 1));
      return f.fixed + num_max(f.traverse, pr.nr_divide * points);
    }
    case kAutoDivFree: return f.fixed + f.traverse + pr.seed_divide;  // one seed division
    default: return f.fixed + f.traverse + pr.affine_setup;  // AFFINE
  }
}

// Nothing predicted within the tolerance (or a triangle that cannot be judged): the most accurate
// divider built (SUBDIV with n = 2 when it is the only one).
uint8_t fallback_method(uint32_t built, uint8_t* subdiv_n) {
  *subdiv_n = 16;
  if (built & (1u << kAutoRecipNr)) return kAutoRecipNr;
  if (built & (1u << kAutoRecipLut)) return kAutoRecipLut;
  if (built & (1u << kAutoSubdiv)) {
    *subdiv_n = 2;
    return kAutoSubdiv;
  }
  return kAutoAffine;
}

// A triangle and tolerance the bounds can judge: every w > 0 and a tolerance > 0.
bool judgeable(const Tri& t, Num tol) {
  bool ok = tol.m > 0;
  for (int i = 0; i < 3; ++i) ok = ok && t.w[i].m > 0;
  return ok;
}

// The bound of the fallback `method` (b holds it: AFFINE's bound, or SUBDIV's terms if it is SUBDIV).
Num fallback_bound(const Bounds& b, const AutoPricing& pr, uint8_t method, unsigned n) {
  return method == kAutoRecipNr    ? b.recip_nr
         : method == kAutoRecipLut ? b.recip_lut
         : method == kAutoSubdiv   ? bound_subdiv(b, pr, n)
                                   : b.affine;
}

// Where no method could save the raster unit more clocks than choosing costs the CPU (the cheapest
// pixel against RECIP_NR's, times the pixels), RECIP_NR when it is built and within the tolerance:
// the choice without comparing (docs/auto.md, "When choosing does not pay").
bool not_worth_choosing(const Footprint& f, const Bounds& b, const AutoPricing& pr, uint32_t built, Num tol) {
  return pr.choice.m != 0 && (built & (1u << kAutoRecipNr)) && f.pixels * pr.pixel_gain < pr.choice &&
         b.recip_nr <= tol;
}

AutoChoice skipped_choice(const Footprint& f, const Bounds& b, const AutoPricing& pr) {
  AutoChoice c;
  c.method = kAutoRecipNr;
  c.within = true;
  c.skipped = true;
  c.bound = num_to_float_up(b.recip_nr);
  c.cycles = num_to_float_up(cycles_of(f, pr, kAutoRecipNr, 0));
  return c;
}

}  // namespace

AutoPricing auto_pricing(const AutoConfig& cfg) {
  AutoPricing p;
  p.cfg = cfg;
  p.base = base_error(cfg);
  p.table_error = table_error(cfg);
  p.newton_error = newton_error(cfg);
  p.setup = num(26 + 7 * cfg.recip_issue_interval);
  p.pixel_cost = num_scale(num(cfg.pixel_cost16), -4);
  p.lut_divide = num_scale(num(cfg.lut_divide_cost16), -4);
  p.nr_divide = num_scale(num(cfg.nr_divide_cost16), -4);
  p.affine_setup = num_scale(num(cfg.affine_setup_cost16), -4);
  p.seed_divide = num(cfg.recip_issue_interval);
  p.choice = num(cfg.choice_cycles);
  p.pixel_gain = num_scale(num(static_cast<int32_t>(pixel_gain16(cfg))), -4);
  return p;
}

AutoNum recip_nr_span_limit(const AutoPricing& pr, AutoNum tol) {
  // RECIP_NR's bound (du/2 + 1) * e + base (cheap_bounds) is within tol for du <= D = 2 (q - 1),
  // q = (tol - base) / e. The truncated arithmetic never computes that bound above its exact
  // value, so D itself is the limit; it is taken 2^-15 q lower for q's own rounding (within 2^-28).
  const Num room = tol - pr.base;
  if (room.m <= 0) return Num{};
  const Num q = room / pr.newton_error;
  return num_scale(q - num(1), 1) - num_scale(q, -15);
}

// AutoBounds' fields and their Bounds counterparts, in the same order.
constexpr float AutoBounds::*kReportedBounds[] = {&AutoBounds::affine,       &AutoBounds::recip_lut,
                                                  &AutoBounds::recip_nr,     &AutoBounds::divfree,
                                                  &AutoBounds::subdiv_slope, &AutoBounds::subdiv_curvature,
                                                  &AutoBounds::span_limit,   &AutoBounds::du};
constexpr Num Bounds::*kBounds[] = {&Bounds::affine,       &Bounds::recip_lut,        &Bounds::recip_nr,
                                    &Bounds::divfree,      &Bounds::subdiv_slope,     &Bounds::subdiv_curvature,
                                    &Bounds::span_limit,   &Bounds::du};
static_assert(sizeof kReportedBounds / sizeof kReportedBounds[0] == sizeof kBounds / sizeof kBounds[0]);

AutoBounds auto_bounds(const AutoTriangle& t, const AutoConfig& cfg, const AutoSampling& s) {
  const Tri tn = tri_of(t);
  const Bounds b = bounds_of(tn, shape_of(tn), auto_pricing(cfg), s);
  AutoBounds r;
  for (uint32_t i = 0; i < sizeof kBounds / sizeof kBounds[0]; ++i) r.*kReportedBounds[i] = num_to_float_up(b.*kBounds[i]);
  return r;
}

float auto_bound_subdiv(const AutoBounds& b, const AutoConfig& cfg, unsigned n) {
  Bounds nb;
  for (uint32_t i = 0; i < sizeof kBounds / sizeof kBounds[0]; ++i) nb.*kBounds[i] = num_from_float(b.*kReportedBounds[i]);
  return num_to_float_up(bound_subdiv(nb, auto_pricing(cfg), n));
}

float auto_cycles(const AutoTriangle& t, const AutoConfig& cfg, uint8_t method, unsigned n) {
  const Tri tn = tri_of(t);
  const AutoPricing pr = auto_pricing(cfg);
  return num_to_float_up(cycles_of(footprint_of(shape_of(tn), pr), pr, method, n));
}

AutoChoice choose_method(const AutoTriangle& t, const AutoConfig& cfg, const AutoSampling& s, uint32_t built,
                         float tolerance) {
  bool ok = positive_input(tolerance);
  for (int i = 0; i < 3; ++i)
    ok = ok && finite_input(t.x[i]) && finite_input(t.y[i]) && finite_input(t.u[i]) && finite_input(t.v[i]) &&
         finite_input(t.w[i]) && positive_input(t.w[i]);
  if (!ok) return choose_method(Tri{}, cfg, s, built, Num{});  // the fallback
  return choose_method(tri_of(t), cfg, s, built, num_from_float(tolerance));
}

AutoChoice choose_method(const AutoTriangleNum& t, const AutoConfig& cfg, const AutoSampling& s, uint32_t built,
                         AutoNum tol) {
  return choose_method(t, auto_pricing(cfg), s, built, tol);
}

AutoChoice choose_method(const AutoTriangleNum& t, const AutoPricing& pr, const AutoSampling& s, uint32_t built,
                         AutoNum tol) {
  AutoChoice c;
  if (!judgeable(t, tol)) {
    c.method = fallback_method(built, &c.subdiv_n);
    return c;
  }
  // The rule (docs/auto.md): among AFFINE, RECIP_LUT, RECIP_NR and DIVFREE, the cheapest within the
  // tolerance (equal costs: the smaller bound, then the first in that order); then SUBDIV with the
  // largest n within it replaces that choice if strictly cheaper. A cost takes a few operations,
  // AFFINE's bound some twenty and SUBDIV's terms about seventy, so those two are found only when
  // their method could still win, and SUBDIV's bound first at n = 64: the same choice, for fewer
  // operations (docs/auto.md, "Arithmetic"; choose_method_exhaustive below is the rule as stated).
  const Shape sh = shape_of(t);
  const Footprint f = footprint_of(sh, pr);
  Bounds b;
  cheap_bounds(sh, pr, s, &b);
  if (not_worth_choosing(f, b, pr, built, tol)) return skipped_choice(f, b, pr);
  // AFFINE's bound and SUBDIV's terms, each found once and only when asked for.
  bool have_affine = false, have_subdiv_terms = false;
  auto affine = [&]() {
    if (!have_affine) b.affine = affine_bound(sh, b.du, pr), have_affine = true;
    return b.affine;
  };
  auto need_subdiv_terms = [&]() {
    if (have_subdiv_terms) return;
    affine();  // (SUBDIV's bound reads it)
    subdiv_terms(t, sh, &b);
    have_subdiv_terms = true;
  };
  Num bound, cycles;  // the choice's, once c.within

  // RECIP_LUT, RECIP_NR and DIVFREE: their bounds are at hand, so each one's cost is found only
  // when it is within the tolerance.
  const uint8_t cheap[3] = {kAutoRecipLut, kAutoRecipNr, kAutoDivFree};
  const Num cheap_bound[3] = {b.recip_lut, b.recip_nr, b.divfree};
  for (int i = 0; i < 3; ++i) {
    if (!(built & (1u << cheap[i])) || !(cheap_bound[i] <= tol)) continue;
    const Num cost = cycles_of(f, pr, cheap[i], 0);
    if (!c.within || cost < cycles || (cost == cycles && cheap_bound[i] < bound)) {
      c.method = cheap[i];
      c.within = true;
      bound = cheap_bound[i];
      cycles = cost;
    }
  }
  // SUBDIV's cost falls as n grows, so if it is not cheaper at n = 64 than the choice so far it
  // never is (AFFINE below can only make the choice cheaper).
  const bool subdiv_built = (built & (1u << kAutoSubdiv)) != 0;
  const Num subdiv_cost_64 = subdiv_built ? cycles_of(f, pr, kAutoSubdiv, 64) : Num{};
  const bool subdiv_may_win = subdiv_built && (!c.within || subdiv_cost_64 < cycles);
  // AFFINE, first in the order (so it wins a tie of cost and bound), comes last. When SUBDIV will
  // need its bound anyway, the bound decides first; otherwise its cost does.
  if (built & (1u << kAutoAffine)) {
    const Num cost = subdiv_may_win ? Num{} : cycles_of(f, pr, kAutoAffine, 0);  // (priced below if not here)
    if (subdiv_may_win || !c.within || cost <= cycles) {
      const Num ab = affine();
      if (ab <= tol) {
        const Num ac = subdiv_may_win ? cycles_of(f, pr, kAutoAffine, 0) : cost;
        if (!c.within || ac < cycles || (ac == cycles && ab <= bound)) {
          c.method = kAutoAffine;
          c.within = true;
          bound = ab;
          cycles = ac;
        }
      }
    }
  }

  // SUBDIV, when it may still win: the longest segment within the tolerance (the bound grows with
  // n: n = 64 first, as it often is; then a binary search over 2..63), if cheaper than the choice.
  if (subdiv_may_win && (!c.within || subdiv_cost_64 < cycles)) {
    need_subdiv_terms();
    unsigned n = 64;
    Num n_bound = bound_subdiv(b, pr, 64);
    if (!(n_bound <= tol)) {
      // Not within at 64: none is if 2 is not; else the largest n in 2..63 within (bound(lo) is).
      n_bound = bound_subdiv(b, pr, 2);
      n = n_bound <= tol ? 2 : 0;
      for (unsigned lo = 2, hi = 63; n != 0 && lo < hi;) {
        const unsigned mid = (lo + hi + 1) / 2;
        const Num mid_bound = bound_subdiv(b, pr, mid);
        if (mid_bound <= tol) lo = mid, n = mid, n_bound = mid_bound;
        else hi = mid - 1;
      }
    }
    if (n != 0) {
      const Num sc = n == 64 ? subdiv_cost_64 : cycles_of(f, pr, kAutoSubdiv, n);
      if (!c.within || sc < cycles) {
        c.method = kAutoSubdiv;
        c.subdiv_n = static_cast<uint8_t>(n);
        c.within = true;
        bound = n_bound;
        cycles = sc;
      }
    }
  }
  if (!c.within) {
    c.method = fallback_method(built, &c.subdiv_n);
    if (c.method == kAutoSubdiv) need_subdiv_terms();
    if (c.method == kAutoAffine) affine();
    bound = fallback_bound(b, pr, c.method, c.subdiv_n);
    cycles = cycles_of(f, pr, c.method, c.subdiv_n);
  }
  c.bound = num_to_float_up(bound);
  c.cycles = num_to_float_up(cycles);
  return c;
}

// The rule as docs/auto.md states it, every bound found: what choose_method must equal.
AutoChoice choose_method_exhaustive(const AutoTriangleNum& t, const AutoConfig& cfg, const AutoSampling& s,
                                    uint32_t built, AutoNum tol) {
  const AutoPricing pr = auto_pricing(cfg);
  AutoChoice c;
  if (!judgeable(t, tol)) {
    c.method = fallback_method(built, &c.subdiv_n);
    return c;
  }
  const Shape sh = shape_of(t);
  const Bounds b = bounds_of(t, sh, pr, s);
  const Footprint f = footprint_of(sh, pr);
  if (not_worth_choosing(f, b, pr, built, tol)) return skipped_choice(f, b, pr);
  Num bound, cycles;
  const uint8_t plain[4] = {kAutoAffine, kAutoRecipLut, kAutoRecipNr, kAutoDivFree};
  const Num plain_bound[4] = {b.affine, b.recip_lut, b.recip_nr, b.divfree};
  for (int i = 0; i < 4; ++i) {
    if (!(built & (1u << plain[i])) || !(plain_bound[i] <= tol)) continue;
    const Num cost = cycles_of(f, pr, plain[i], 0);
    if (!c.within || cost < cycles || (cost == cycles && plain_bound[i] < bound))
      c.method = plain[i], c.within = true, bound = plain_bound[i], cycles = cost;
  }
  for (unsigned n = 64; (built & (1u << kAutoSubdiv)) && n >= 2; --n) {
    const Num nb = bound_subdiv(b, pr, n);
    if (!(nb <= tol)) continue;
    const Num cost = cycles_of(f, pr, kAutoSubdiv, n);
    if (!c.within || cost < cycles)
      c.method = kAutoSubdiv, c.subdiv_n = static_cast<uint8_t>(n), c.within = true, bound = nb, cycles = cost;
    break;  // the largest n within the tolerance
  }
  if (!c.within) {
    c.method = fallback_method(built, &c.subdiv_n);
    bound = fallback_bound(b, pr, c.method, c.subdiv_n);
    cycles = cycles_of(f, pr, c.method, c.subdiv_n);
  }
  c.bound = num_to_float_up(bound);
  c.cycles = num_to_float_up(cycles);
  return c;
}

}  // namespace htx::fw
