#include "ref_raster.hpp"

#include <algorithm>
#include <cmath>

#include "exact_orient.hpp"

namespace htx::ref {

namespace {

// Pixel index range [lo, hi] whose centres (k + 0.5) lie within [a, b], clipped to [0, n - 1].
void centre_range(double a, double b, int n, int& lo, int& hi) {
  const double flo = std::ceil(std::clamp(a - 0.5, -1.0, static_cast<double>(n)));
  const double fhi = std::floor(std::clamp(b - 0.5, -1.0, static_cast<double>(n)));
  lo = std::max(0, static_cast<int>(flo));
  hi = std::min(n - 1, static_cast<int>(fhi));
}

}  // namespace

TriSetup setup_triangle(const ScreenTri& tri, int width, int height) {
  TriSetup s;
  for (const ScreenVertex& v : tri.v)
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return s;
  const auto& a = tri.v[0];
  const auto& b = tri.v[1];
  const auto& c = tri.v[2];
  const int sign = orient2d_sign(a.x, a.y, b.x, b.y, c.x, c.y);
  if (sign == 0) return s;
  if (sign > 0) {
    s.order[1] = 1;
    s.order[2] = 2;
  } else {
    s.order[1] = 2;
    s.order[2] = 1;
  }
  for (int k = 0; k < 3; ++k) s.p[k] = {tri.v[s.order[k]].x, tri.v[s.order[k]].y};
  s.area2 = (s.p[1][0] - s.p[0][0]) * (s.p[2][1] - s.p[0][1]) -
            (s.p[1][1] - s.p[0][1]) * (s.p[2][0] - s.p[0][0]);
  for (int k = 0; k < 3; ++k) {
    const auto& p = s.p[k];
    const auto& q = s.p[(k + 1) % 3];
    const double dx = q[0] - p[0], dy = q[1] - p[1];
    // y points down and the inside is where the edge function is positive: an edge going up is a
    // left edge, a horizontal edge going right is a top edge.
    s.include_edge[k] = dy < 0 || (dy == 0 && dx > 0);
  }
  const double minx = std::min({a.x, b.x, c.x}), maxx = std::max({a.x, b.x, c.x});
  const double miny = std::min({a.y, b.y, c.y}), maxy = std::max({a.y, b.y, c.y});
  centre_range(minx, maxx, width, s.x0, s.x1);
  centre_range(miny, maxy, height, s.y0, s.y1);
  s.empty = s.x0 > s.x1 || s.y0 > s.y1;
  return s;
}

bool covers(const TriSetup& s, int i, int j) {
  const double x = i + 0.5, y = j + 0.5;
  for (int k = 0; k < 3; ++k) {
    const auto& p = s.p[k];
    const auto& q = s.p[(k + 1) % 3];
    const int e = orient2d_sign(p[0], p[1], q[0], q[1], x, y);
    if (e < 0 || (e == 0 && !s.include_edge[k])) return false;
  }
  return true;
}

Barycentric barycentric(const TriSetup& s, double x, double y) {
  Barycentric r{};
  for (int k = 0; k < 3; ++k) {
    // The weight of p[k] is the edge function of the opposite edge p[k+1] -> p[k+2], over the area.
    const auto& p = s.p[(k + 1) % 3];
    const auto& q = s.p[(k + 2) % 3];
    const double e = (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]);
    const int in = s.order[k];
    r.l[in] = e;
    r.dx[in] = -(q[1] - p[1]);
    r.dy[in] = q[0] - p[0];
  }
  return r;
}

}  // namespace htx::ref
