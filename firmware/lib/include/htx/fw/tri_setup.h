// The raster unit's triangle setup in freestanding C++17 (docs/model.md, "Setup"): coverage (the
// determinant, the edge functions with the top-left rule, the pixel box), the shared reciprocal
// unit (table and Newton steps), attribute planes and the divider's fixed-point division. The
// same integer expressions as the host model (htx/model/raster_setup.hpp, recip.hpp), bit for bit,
// so that firmware can do setup for a raster unit that leaves it out (docs/area.md, "Setup in
// firmware"). Coverage and the reciprocal table are the model's too (it calls them, as it uses the
// vertex record's encoder); the rest is held to the model's checked 128-bit arithmetic by
// tests/unit/fw_tri_setup_test.cpp.
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

// The same for W <= 30, in 64-bit arithmetic only (what the firmware's plane records use: the rv32im
// CPU's code for the 128-bit paths costs RAM it does not have; docs/firmware.md).
uint64_t recip_mantissa_64(const RecipSetup& p, uint64_t mantissa);
RecipResult reciprocal_64(const RecipSetup& p, uint64_t x);

// A plane on the subpixel grid: value(px, py) 2^F = base + gx (px - x0) + gy (py - y0), F the
// gradients' fraction bits; base = a0 2^F.
struct PlaneSetup {
  Int128 base, gx, gy;
  int64_t x0 = 0, y0 = 0;
};
// The plane through the setup's (reordered) vertices with values[3]; inv_det = 1/det.
PlaneSetup make_plane(const CoverageSetup& s, const Int128 values[3], RecipResult inv_det, uint32_t frac_bits);
// The same for vertex values |values[i]| < 2^36 (every `icebreaker` plane's), whose numerators
// n_x, n_y fit 64 bits with any record's coordinates (|deltas| < 2^25): only the product by 1/det
// is 128-bit. make_plane takes this path wherever the values allow.
void make_plane_64(const CoverageSetup& s, const int64_t values[3], RecipResult inv_det, uint32_t frac_bits,
                   PlaneSetup* out);

// The vertex value of setup's attribute plane `plane` (0 z, 1 q, 2 uq, 3 vq, 4..7 the colour
// channels r, g, b, a), signed.
inline int64_t plane_value(const VertexRecord& v, int plane) {
  switch (plane) {
    case 0: return v.z;
    case 1: return v.q;
    case 2: return v.uq;
    case 3: return v.vq;
    default: return (v.rgba >> (8 * (plane - 4))) & 0xFF;
  }
}

// num / den (den > 0) with frac_bits fraction bits, as the divider forms it: den normalised to M
// 2^s, num' = round(num 2^-s) (exact for s <= 0), result round(num' R 2^(frac_bits - 2W + 1)).
int64_t divide_fixed(const RecipSetup& p, Int128 num, uint64_t den, uint32_t frac_bits);
// The same for W <= 30 where num 2^-s fits 64 bits; false where it does not.
bool divide_fixed_64(const RecipSetup& p, int64_t num, uint64_t den, uint32_t frac_bits, int64_t* out);

// A configuration's setup parameters, those of the model's named configurations (htx::model_config;
// tests/system/setup_check_test.cpp checks that they agree). recip.table is left null.
struct SetupParams {
  RecordFormat format;
  RecipSetup recip;
  uint32_t grad_frac_bits, texcoord_frac_bits;
  uint32_t lod_grad_bits;  // the LOD unit's block-shifted gradients (DIVFREE's and trilinear's)
};
inline constexpr SetupParams kIcebreakerSetup{{12, 16, 24, 13}, {8, 2, 24, 2, nullptr}, 16, 10, 16};
inline constexpr SetupParams kFullSetup{{16, 24, 32, 16}, {10, 2, 32, 2, nullptr}, 24, 16, 24};

}  // namespace htx::fw
