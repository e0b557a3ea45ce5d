// The raster unit's triangle setup in freestanding C++17 (docs/model.md, "Setup"): coverage (the
// determinant, the edge functions with the top-left rule, the pixel box), the shared reciprocal
// unit (table and Newton steps), attribute planes and the divider's fixed-point division. The
// same integer expressions as the host model (htx/model/raster_setup.hpp, recip.hpp), bit for bit,
// so that firmware can do setup for a raster unit that leaves it out (docs/area.md, "Setup in
// firmware"); tests/unit/fw_tri_setup_test.cpp holds it to the model.
#pragma once

#include <stdint.h>

#include "htx/fw/int128.h"
#include "htx/fw/vertex_record.h"

namespace htx::fw {

// An edge function on the 1/256-pixel grid: E(px, py) = a (px - x0) + b (py - y0); a pixel
// centre is covered when E >= threshold (0 on top and left edges, 1 elsewhere).
struct SetupEdge {
  int64_t a = 0, b = 0;
  int64_t x0 = 0, y0 = 0;
  int64_t threshold = 0;
};

struct CoverageSetup {
  bool empty = true;     // zero area, or no pixel centre of the screen inside the bounding box
  TriangleRecord rec;    // vertices 1 and 2 swapped when the determinant was negative
  int64_t det = 0;       // |determinant| in 1/65536 pixel^2
  SetupEdge edges[3];
  int32_t x_lo = 0, x_hi = -1, y_lo = 0, y_hi = -1;  // pixel box, clipped to the screen
};

// Coverage setup of a triangle on a width x height screen. Both windings are drawn.
void setup_coverage(const TriangleRecord& rec, int32_t width, int32_t height, CoverageSetup* out);

// The reciprocal unit's parameters: a k-bit table with g guard bits, W-bit mantissas, Newton steps.
// table: the 2^k entries (recip_fill_table), or null to compute each entry where it is used (a
// 64-bit division, about a thousand cycles on the rv32im CPU).
struct RecipSetup {
  uint32_t k = 10, g = 2, width = 32, steps = 0;
  const uint32_t* table = nullptr;
};

// round(2^(k+g+1) / midpoint of table interval i).
uint32_t recip_table_entry(uint32_t k, uint32_t g, uint32_t i);
// Fills table[0 .. 2^k - 1] with recip_table_entry(k, g, i).
void recip_fill_table(uint32_t k, uint32_t g, uint32_t* table);
// R ~ 2^W / m for a mantissa M in [2^(W-1), 2^W): the table entry, then `steps` Newton steps.
uint64_t recip_mantissa(const RecipSetup& p, uint64_t mantissa);
// The W-bit mantissa of x > 0 (truncated) and the index of its leading one.
uint64_t recip_normalise(uint64_t x, uint32_t width, int32_t* msb);

// 1/x ~ value 2^-shift for an integer x > 0.
struct RecipResult {
  uint64_t value = 0;
  int32_t shift = 0;
};
RecipResult reciprocal(const RecipSetup& p, uint64_t x);

// A plane on the subpixel grid: value(px, py) 2^F = base + gx (px - x0) + gy (py - y0), F the
// gradients' fraction bits; base = a0 2^F.
struct PlaneSetup {
  Int128 base, gx, gy;
  int64_t x0 = 0, y0 = 0;
};
// The plane through the setup's (reordered) vertices with values[3]; inv_det = 1/det.
PlaneSetup make_plane(const CoverageSetup& s, const Int128 values[3], RecipResult inv_det, uint32_t frac_bits);

// num / den (den > 0) with frac_bits fraction bits, as the divider forms it: den normalised to M
// 2^s, num' = round(num 2^-s) (exact for s <= 0), result round(num' R 2^(frac_bits - 2W + 1)).
int64_t divide_fixed(const RecipSetup& p, Int128 num, uint64_t den, uint32_t frac_bits);

}  // namespace htx::fw
