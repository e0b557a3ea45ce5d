// The LOD unit (docs/model.md, "Level of detail"): a base-2 logarithm from a leading-one detector
// and a table of log2(1 + f), and the isotropic LOD of a pixel from its plane values:
//   lod = log2 max(|d(u,v)/dx|, |d(u,v)/dy|), with du/dx = (dU/dx - u dQ/dx) / Q per pixel.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/model/wide.hpp"

namespace htx::model {

class Log2Unit {
 public:
  // index_bits mantissa bits below the leading one address the table; results carry out_frac_bits.
  Log2Unit(unsigned index_bits, unsigned out_frac_bits);
  // log2(x) * 2^out_frac_bits for x > 0 (the table holds log2 of each interval's midpoint).
  int64_t log2(u128 x) const;
  unsigned out_frac_bits() const { return out_frac_bits_; }
  // Table entry i: round(2^out * log2(1 + (i + 1/2) / 2^index_bits)), computed by exact squaring.
  static uint32_t table_entry(unsigned index_bits, unsigned out_frac_bits, uint32_t i);

 private:
  unsigned index_bits_, out_frac_bits_;
  std::vector<uint32_t> table_;
};

// Inputs of the LOD unit at one pixel. Gradients are per subpixel scaled by 2^(grad_frac_bits -
// grad_shift) (see lod_gradient_shift), the accumulator q by 2^grad_frac_bits, the coordinates u, v
// (local, before the texel offset) carry tex_frac_bits.
struct LodInputs {
  i128 q = 0;               // Q plane accumulator (> 0)
  i128 gux = 0, guy = 0;    // uq plane gradients
  i128 gvx = 0, gvy = 0;    // vq plane gradients
  i128 gqx = 0, gqy = 0;    // q plane gradients
  int grad_shift = 0;       // the gradients above were shifted right by this much
  int64_t u = 0, v = 0;     // local texel coordinates with tex_frac_bits
  unsigned tex_frac_bits = 16;
};

// The per-triangle block exponent: the right shift that leaves the largest of the six gradients
// with at most `bits` bits including the sign (0 when they already fit).
int lod_gradient_shift(const i128 (&gradients)[6], unsigned bits);

// LOD with lod_frac_bits fractional bits (may be negative: magnification). The unit's log tables run
// two bits finer than the result, which is rounded to nearest. Returns INT32_MIN when both
// derivative vectors are zero.
int32_t compute_lod(const Log2Unit& unit, const LodInputs& in, unsigned lod_frac_bits);

}  // namespace htx::model
