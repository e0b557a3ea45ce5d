#include "htx/model/raster_setup.hpp"

#include <algorithm>

namespace htx::model {

i128 Plane::at(int64_t px, int64_t py) const {
  return add_checked(add_checked(base, mul_checked(gx, px - x0)), mul_checked(gy, py - y0));
}

TriSetup setup_coverage(const fw::TriangleRecord& rec, int width, int height) {
  TriSetup s;
  fw::setup_coverage(rec, width, height, &s);
  return s;
}

bool row_span(const TriSetup& s, int y, int* x_first, int* x_last) {
  int64_t lo = s.x_lo, hi = s.x_hi;
  const int64_t py = 256 * int64_t{y} + 128;
  for (const Edge& e : s.edges) {
    // E(x) = 256 a x + k for pixel column x; need E >= threshold.
    const int64_t k = e.a * (128 - e.x0) + e.b * (py - e.y0);
    const int64_t need = e.threshold - k;
    if (e.a > 0) {
      lo = std::max<int64_t>(lo, static_cast<int64_t>(ceil_div(need, 256 * e.a)));
    } else if (e.a < 0) {
      hi = std::min<int64_t>(hi, static_cast<int64_t>(floor_div(need, 256 * e.a)));
    } else if (need > 0) {
      return false;
    }
    if (lo > hi) return false;
  }
  *x_first = static_cast<int>(lo);
  *x_last = static_cast<int>(hi);
  return true;
}

Plane make_plane(const TriSetup& s, const std::array<i128, 3>& a, const DetReciprocal& inv_det,
                 unsigned frac_bits) {
  const auto& v = s.rec.v;
  const i128 dx1 = int64_t{v[1].x} - v[0].x, dy1 = int64_t{v[1].y} - v[0].y;
  const i128 dx2 = int64_t{v[2].x} - v[0].x, dy2 = int64_t{v[2].y} - v[0].y;
  const i128 da1 = a[1] - a[0], da2 = a[2] - a[0];
  const i128 nx = mul_checked(da1, dy2) - mul_checked(da2, dy1);
  const i128 ny = mul_checked(da2, dx1) - mul_checked(da1, dx2);
  const int shift = inv_det.shift - static_cast<int>(frac_bits);
  Plane p;
  p.base = mul_checked(a[0], static_cast<i128>(1) << frac_bits);
  p.gx = shift_round(mul_checked(nx, static_cast<i128>(inv_det.value)), shift);
  p.gy = shift_round(mul_checked(ny, static_cast<i128>(inv_det.value)), shift);
  p.x0 = v[0].x;
  p.y0 = v[0].y;
  return p;
}

}  // namespace htx::model
