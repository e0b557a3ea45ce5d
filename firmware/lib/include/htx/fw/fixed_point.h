// Fixed-point helpers shared by the firmware and the host model. Freestanding: no libm, no C++
// standard library, so the rv32im build (soft double) and the host give bit-identical results.
#pragma once

#include <stdint.h>

namespace htx::fw {

// Nearest integer to x, ties toward +infinity (floor(x + 0.5)). NaN gives 0; values beyond
// +-2^62 saturate there. This is the one rounding rule of every encoder in this library.
int64_t round_nearest(double x);

// The exponent e with x * 2^e in [0.5, 1) for finite x > 0 (like -frexp). Returns 0 for x <= 0.
int normalising_exponent(double x);

// x * 2^e, exact for results in the normal range (repeated multiplication by powers of two).
double scale_by_pow2(double x, int e);

// Clamps x into [lo, hi].
inline double clamp_double(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

// Number of leading zeros of a 64-bit word (64 for zero).
int count_leading_zeros64(uint64_t x);

}  // namespace htx::fw
