// The shared reciprocal unit (docs/model.md, "Reciprocal unit"): normalise, k-bit table with g guard
// bits (DasSarma-Matula midpoint-reciprocal table), then Newton-Raphson steps in a W-bit datapath.
// It serves triangle setup (1/determinant) and per-pixel division (1/q).
#pragma once

#include <cstdint>

#include "htx/model/wide.hpp"

namespace htx::model {

struct RecipParams {
  unsigned k = 10;      // table index bits
  unsigned g = 2;       // guard bits: entries have k + g bits after the leading one
  unsigned width = 32;  // W: mantissa M has W-1 fraction bits, the result W fraction bits
  unsigned steps = 0;   // Newton-Raphson steps
};

// Table entry i (0 <= i < 2^k): round(2^(k+g+1) / midpoint of [1 + i/2^k, 1 + (i+1)/2^k)), i.e. the
// reciprocal of the interval midpoint with k+g+1 fraction bits, value in (2^(k+g), 2^(k+g+1)).
uint32_t recip_table_entry(unsigned k, unsigned g, uint32_t i);

// Reciprocal of a normalised mantissa M in [2^(W-1), 2^W) (m = M / 2^(W-1) in [1, 2)). Returns R
// with W fraction bits (r = R / 2^W ~ 1/m, in (0.5, 1]): the table entry, then `steps` times
//   e = (M * R) >> (W-1);  R = (R * (2^(W+1) - e) + 2^(W-1)) >> W.
uint64_t recip_mantissa(const RecipParams& p, uint64_t mantissa);

// 1/x for an integer x > 0: 1/x ~ value * 2^-shift. x is normalised to W bits by truncation.
struct Reciprocal {
  uint64_t value = 0;
  int shift = 0;
};
Reciprocal reciprocal(const RecipParams& p, u128 x);

// Normalised W-bit mantissa of x > 0 (truncated) and the position of its leading one.
uint64_t normalise(u128 x, unsigned width, int* msb);

// The divider: num / den (den > 0) as signed fixed point with frac_bits fraction bits. den is
// normalised to its W-bit mantissa M by a shift s (den ~ M 2^s); num is shifted by the same s
// (rounded), so the multiplier sees num' = round(num 2^-s) of about (quotient bits + W) bits, and
// the result is round(num' R 2^(frac_bits - 2W + 1)).
int64_t divide_fixed(const RecipParams& p, i128 num, i128 den, unsigned frac_bits);

}  // namespace htx::model
