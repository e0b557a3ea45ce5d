#include "htx/render/auto_method.h"

namespace htx::render {

namespace {

constexpr int64_t kRangeCap = int64_t{1} << 40;

// floor(a), at most `cap`; -1 for a <= 0.
int64_t num_floor_capped(fw::AutoNum a, int64_t cap) {
  if (a.m <= 0) return -1;
  if (a.e >= 0) return a.e > 24 ? cap : (static_cast<int64_t>(a.m) << a.e) < cap ? static_cast<int64_t>(a.m) << a.e : cap;
  return a.e <= -31 ? 0 : static_cast<int64_t>(a.m >> -a.e);
}

int64_t magnitude64(int64_t v) { return v < 0 ? -v : v; }

int64_t range_of(int32_t a, int32_t b, int32_t c) {
  int32_t lo = a, hi = a;
  if (b < lo) lo = b;
  if (b > hi) hi = b;
  if (c < lo) lo = c;
  if (c > hi) hi = c;
  return static_cast<int64_t>(hi) - lo;
}

// The chooser's first rule tested on the fixed-point vertices (AutoMesh's skip_* limits).
bool skip_in_integers(const ScreenVert* const v[3], const AutoMesh& mesh) {
  const int64_t dx1 = static_cast<int64_t>(v[1]->x) - v[0]->x, dy2 = static_cast<int64_t>(v[2]->y) - v[0]->y;
  const int64_t dx2 = static_cast<int64_t>(v[2]->x) - v[0]->x, dy1 = static_cast<int64_t>(v[1]->y) - v[0]->y;
  // Differences beyond 2^16 pixels are left to the chooser (their products could overflow).
  constexpr int64_t kDifferenceCap = kRangeCap >> 16;
  if (magnitude64(dx1) >= kDifferenceCap || magnitude64(dx2) >= kDifferenceCap || magnitude64(dy1) >= kDifferenceCap ||
      magnitude64(dy2) >= kDifferenceCap)
    return false;
  const int64_t p1 = dx1 * dy2, p2 = dx2 * dy1;
  // The chooser's determinant is within a few 2^-30 of |p1| + |p2| of the exact one: the slack
  // covers 2^-20 of it and two units.
  const int64_t area2 = magnitude64(p1 - p2) + ((magnitude64(p1) + magnitude64(p2)) >> 20) + 2;
  return area2 < kRangeCap && area2 * static_cast<int64_t>(mesh.skip_gain16) < mesh.skip_area_limit &&
         range_of(v[0]->attr->s, v[1]->attr->s, v[2]->attr->s) <= mesh.skip_s_range &&
         range_of(v[0]->attr->t, v[1]->attr->t, v[2]->attr->t) <= mesh.skip_t_range;
}

}  // namespace

fw::AutoTriangleNum auto_triangle(const ScreenVert* const v[3], TexSize tex) {
  // Exact: every coordinate is an integer times a power of two (1/256 pixel, Q16.16 w, s and t).
  fw::AutoTriangleNum t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = fw::num_scale(fw::num_from_int(v[i]->x), -8);
    t.y[i] = fw::num_scale(fw::num_from_int(v[i]->y), -8);
    t.w[i] = fw::num_scale(fw::num_from_int(v[i]->w), -16);
    t.u[i] = fw::num_scale(fw::num_from_int(v[i]->attr->s), tex.log2_width - 16);
    t.v[i] = fw::num_scale(fw::num_from_int(v[i]->attr->t), tex.log2_height - 16);
  }
  return t;
}

fw::AutoNum auto_tolerance(int64_t tol_q16) {
  const int32_t tol32 = tol_q16 > INT32_MAX ? INT32_MAX : tol_q16 < 0 ? 0 : static_cast<int32_t>(tol_q16);
  return fw::num_scale(fw::num_from_int(tol32), -16);
}

AutoMesh auto_mesh(const fw::AutoConfig& cfg, fw::AutoSampling sampling, TexSize tex, fw::AutoNum tolerance,
                   uint32_t built) {
  AutoMesh m;
  m.pricing = fw::auto_pricing(cfg);
  m.sampling = sampling;
  m.tolerance = tolerance;
  m.built = built;
  m.tex = tex;
  if (cfg.choice_cycles == 0 || !(built & (1u << fw::kAutoRecipNr))) return m;
  // The chooser's test, pixels * gain < choice_cycles with pixels = |area2| / 2^17 and gain =
  // gain16 / 16, is |area2| * gain16 < choice_cycles * 2^21 in integers.
  m.skip_gain16 = fw::pixel_gain16(cfg);
  const fw::AutoNum du = fw::recip_nr_span_limit(m.pricing, tolerance);
  m.skip_s_range = num_floor_capped(fw::num_scale(du, 16 - tex.log2_width), kRangeCap);
  m.skip_t_range = num_floor_capped(fw::num_scale(du, 16 - tex.log2_height), kRangeCap);
  if (m.skip_s_range < 0 || m.skip_t_range < 0) return m;
  m.skip_area_limit = static_cast<int64_t>(cfg.choice_cycles) << 21;
  return m;
}

fw::AutoChoice auto_method(const ScreenVert* const v[3], const AutoMesh& mesh) {
  if (mesh.skip_area_limit != 0 && skip_in_integers(v, mesh)) {
    fw::AutoChoice c;
    c.method = fw::kAutoRecipNr;
    c.within = true;
    c.skipped = true;
    return c;
  }
  return fw::choose_method(auto_triangle(v, mesh.tex), mesh.pricing, mesh.sampling, mesh.built, mesh.tolerance);
}

}  // namespace htx::render
