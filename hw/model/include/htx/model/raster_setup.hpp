// Triangle setup and coverage of the raster unit (docs/model.md, "Setup" and "Traversal"):
// integer edge functions on the 1/256-pixel grid, the determinant and its reciprocal from the
// shared reciprocal unit, and fixed-point attribute planes.
#pragma once

#include <array>
#include <cstdint>

#include "htx/fw/tri_setup.h"
#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/wide.hpp"

namespace htx::model {

// A plane on the subpixel grid: value(px, py) * 2^F = base + gx * (px - x0) + gy * (py - y0), where
// px, py are in 1/256 pixel and F = grad_frac_bits. base = a0 * 2^F exactly.
struct Plane {
  i128 base = 0, gx = 0, gy = 0;
  int64_t x0 = 0, y0 = 0;
  i128 at(int64_t px, int64_t py) const;  // exact: equals stepping base by gx, gy
};

// Coverage is the firmware's own code (firmware/lib tri_setup.h, all 64-bit integers), as the
// vertex record's encoder is: one implementation of the edges, the top-left rule and the box.
using Edge = fw::SetupEdge;
using TriSetup = fw::CoverageSetup;

// Coverage setup. Winding: both drawn (a negative determinant swaps vertices 1 and 2).
TriSetup setup_coverage(const fw::TriangleRecord& rec, int width, int height);

// Pixels [*x_first, *x_last] of row y covered by the triangle (exact top-left rule, pixel centres at
// +0.5), clipped to the box. Returns false when the row has none.
bool row_span(const TriSetup& s, int y, int* x_first, int* x_last);

// Plane of per-vertex integer values through the setup's vertices; inv_det is 1/det from the
// reciprocal unit (value * 2^-shift). Gradients are rounded to grad_frac_bits below the unit.
struct DetReciprocal {
  uint64_t value = 0;
  int shift = 0;
};
Plane make_plane(const TriSetup& s, const std::array<i128, 3>& values, const DetReciprocal& inv_det,
                 unsigned frac_bits);

}  // namespace htx::model
