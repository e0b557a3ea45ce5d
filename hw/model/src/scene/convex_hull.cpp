#include "convex_hull.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_set>

namespace htx {

namespace {

struct Face {
  uint32_t v[3];
  Vec3 n;  // outward (b - a) x (c - a)
};

Face make_face(const std::vector<Vec3>& p, uint32_t a, uint32_t b, uint32_t c) {
  return {{a, b, c}, cross(p[b] - p[a], p[c] - p[a])};
}

uint64_t edge_key(uint32_t a, uint32_t b) { return static_cast<uint64_t>(a) << 32 | b; }

}  // namespace

std::vector<std::array<uint32_t, 3>> convex_hull(const std::vector<Vec3>& p) {
  if (p.size() < 4) throw std::invalid_argument("convex hull needs at least 4 points");
  double extent = 0;
  for (const Vec3& q : p) extent = std::max({extent, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
  const double eps = 1e-12 * extent * extent * extent;

  // Initial tetrahedron from points 0 and the first ones that span a line, a plane and a volume.
  uint32_t i1 = 1, i2 = 0, i3 = 0;
  const auto n = static_cast<uint32_t>(p.size());
  while (i1 < n && length(p[i1] - p[0]) <= 1e-9 * extent) ++i1;
  for (i2 = i1 + 1; i2 < n && length(cross(p[i1] - p[0], p[i2] - p[0])) <= 1e-9 * extent * extent; ++i2) {}
  for (i3 = i2 + 1; i3 < n; ++i3)
    if (std::fabs(dot(cross(p[i1] - p[0], p[i2] - p[0]), p[i3] - p[0])) > 1e-9 * extent * extent * extent) break;
  if (i1 >= n || i2 >= n || i3 >= n) throw std::invalid_argument("convex hull of coplanar points");

  std::vector<Face> faces;
  const uint32_t tet[4] = {0, i1, i2, i3};
  for (int k = 0; k < 4; ++k) {
    uint32_t a = tet[(k + 1) % 4], b = tet[(k + 2) % 4], c = tet[(k + 3) % 4];
    const uint32_t other = tet[k];
    Face f = make_face(p, a, b, c);
    if (dot(f.n, p[other] - p[a]) > 0) f = make_face(p, a, c, b);
    faces.push_back(f);
  }

  std::vector<char> used(n, 0);
  for (uint32_t t : tet) used[t] = 1;
  for (uint32_t i = 0; i < n; ++i) {
    if (used[i]) continue;
    std::vector<Face> kept, visible;
    std::unordered_set<uint64_t> visible_edges;
    for (const Face& f : faces) {
      if (dot(f.n, p[i] - p[f.v[0]]) > eps) {
        visible.push_back(f);
        for (int k = 0; k < 3; ++k) visible_edges.insert(edge_key(f.v[k], f.v[(k + 1) % 3]));
      } else {
        kept.push_back(f);
      }
    }
    if (visible.empty()) continue;  // inside the hull
    // Horizon edges (a visible face's edge whose twin is not visible) in a deterministic order.
    for (const Face& f : visible)
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = f.v[k], b = f.v[(k + 1) % 3];
        if (!visible_edges.count(edge_key(b, a))) kept.push_back(make_face(p, a, b, i));
      }
    faces = std::move(kept);
  }
  std::vector<std::array<uint32_t, 3>> out;
  out.reserve(faces.size());
  for (const Face& f : faces) out.push_back({f.v[0], f.v[1], f.v[2]});
  return out;
}

}  // namespace htx
