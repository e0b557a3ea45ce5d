#include "htx/model/raster_setup.hpp"

#include <algorithm>
#include <utility>

namespace htx::model {

i128 Plane::at(int64_t px, int64_t py) const {
  return add_checked(add_checked(base, mul_checked(gx, px - x0)), mul_checked(gy, py - y0));
}

TriSetup setup_coverage(const fw::TriangleRecord& rec, int width, int height) {
  TriSetup s;
  s.rec = rec;
  auto& v = s.rec.v;
  const int64_t det = (int64_t{v[1].x} - v[0].x) * (int64_t{v[2].y} - v[0].y) -
                      (int64_t{v[2].x} - v[0].x) * (int64_t{v[1].y} - v[0].y);
  if (det == 0) return s;
  if (det < 0) std::swap(v[1], v[2]);
  s.det = det < 0 ? -det : det;
  for (int k = 0; k < 3; ++k) {
    const auto& p = v[k];
    const auto& q = v[(k + 1) % 3];
    const int64_t dx = int64_t{q.x} - p.x, dy = int64_t{q.y} - p.y;
    Edge& e = s.edges[k];
    e.a = -dy;
    e.b = dx;
    e.x0 = p.x;
    e.y0 = p.y;
    // y points down, inside is E > 0: an edge going up is a left edge, a horizontal edge going
    // right is a top edge. Pixels exactly on those belong to this triangle.
    e.threshold = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
  }
  const int64_t minx = std::min({int64_t{v[0].x}, int64_t{v[1].x}, int64_t{v[2].x}});
  const int64_t maxx = std::max({int64_t{v[0].x}, int64_t{v[1].x}, int64_t{v[2].x}});
  const int64_t miny = std::min({int64_t{v[0].y}, int64_t{v[1].y}, int64_t{v[2].y}});
  const int64_t maxy = std::max({int64_t{v[0].y}, int64_t{v[1].y}, int64_t{v[2].y}});
  // Pixel centres 256 i + 128 inside [min, max].
  const int64_t xl = static_cast<int64_t>(ceil_div(minx - 128, 256));
  const int64_t xh = static_cast<int64_t>(floor_div(maxx - 128, 256));
  const int64_t yl = static_cast<int64_t>(ceil_div(miny - 128, 256));
  const int64_t yh = static_cast<int64_t>(floor_div(maxy - 128, 256));
  s.x_lo = static_cast<int>(std::max<int64_t>(xl, 0));
  s.x_hi = static_cast<int>(std::min<int64_t>(xh, width - 1));
  s.y_lo = static_cast<int>(std::max<int64_t>(yl, 0));
  s.y_hi = static_cast<int>(std::min<int64_t>(yh, height - 1));
  s.empty = s.x_lo > s.x_hi || s.y_lo > s.y_hi;
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
