// 3D convex hull (incremental), used to build random closed meshes whose front faces cover their
// silhouette exactly once.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "htx/model/linalg.hpp"

namespace htx {

// Triangles of the hull, counter-clockwise seen from outside, indexing `points`. Points inside the
// hull (or on it within rounding) are left out. Throws std::invalid_argument when the points are
// fewer than four or all (nearly) coplanar.
std::vector<std::array<uint32_t, 3>> convex_hull(const std::vector<Vec3>& points);

}  // namespace htx
