// A 128-bit two's-complement integer for freestanding C++17: the raster unit's setup arithmetic
// needs products up to about 110 bits (docs/model.md lists the widths), and GCC has no __int128
// on rv32. Only what triangle setup uses: sums, products (the low 128 bits, which are the same for
// signed and unsigned operands), shifts, comparisons and round-to-nearest shifts. Nothing traps:
// a result that does not fit wraps modulo 2^128, where the host model reports an overflow (the
// record formats keep every value in range).
#pragma once

#include <stdint.h>

namespace htx::fw {

struct Int128 {
  uint64_t lo = 0;
  uint64_t hi = 0;  // bit 63 is the sign
};

inline constexpr Int128 i128_from(int64_t v) {
  return Int128{static_cast<uint64_t>(v), v < 0 ? ~uint64_t{0} : 0};
}
inline constexpr Int128 u128_from(uint64_t v) { return Int128{v, 0}; }

inline constexpr bool i128_negative(Int128 a) { return (a.hi >> 63) != 0; }
inline constexpr bool i128_is_zero(Int128 a) { return (a.lo | a.hi) == 0; }
inline constexpr bool i128_eq(Int128 a, Int128 b) { return a.lo == b.lo && a.hi == b.hi; }

inline constexpr Int128 i128_add(Int128 a, Int128 b) {
  const uint64_t lo = a.lo + b.lo;
  return Int128{lo, a.hi + b.hi + (lo < a.lo ? 1u : 0u)};
}
inline constexpr Int128 i128_neg(Int128 a) { return i128_add(Int128{~a.lo, ~a.hi}, Int128{1, 0}); }
inline constexpr Int128 i128_sub(Int128 a, Int128 b) { return i128_add(a, i128_neg(b)); }

// a < b as signed numbers.
inline constexpr bool i128_less(Int128 a, Int128 b) {
  const int64_t ah = static_cast<int64_t>(a.hi), bh = static_cast<int64_t>(b.hi);
  return ah != bh ? ah < bh : a.lo < b.lo;
}
// a < b as unsigned numbers.
inline constexpr bool u128_less(Int128 a, Int128 b) { return a.hi != b.hi ? a.hi < b.hi : a.lo < b.lo; }

// The full 128-bit product of two unsigned 64-bit numbers, from four 32 x 32-bit products.
inline constexpr Int128 mul_64x64(uint64_t a, uint64_t b) {
  const uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
  const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
  return Int128{(p00 & 0xFFFFFFFFu) | (mid << 32), p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32)};
}

// The low 128 bits of a b (signed or unsigned alike).
inline constexpr Int128 i128_mul(Int128 a, Int128 b) {
  Int128 p = mul_64x64(a.lo, b.lo);
  p.hi += a.lo * b.hi + a.hi * b.lo;
  return p;
}

// a 2^s for 0 <= s < 128 (bits shifted out are lost).
inline constexpr Int128 i128_shl(Int128 a, unsigned s) {
  if (s == 0) return a;
  if (s >= 64) return Int128{0, a.lo << (s - 64)};
  return Int128{a.lo << s, (a.hi << s) | (a.lo >> (64 - s))};
}

// floor(a 2^-s) for 0 <= s < 128 (arithmetic shift).
inline constexpr Int128 i128_sar(Int128 a, unsigned s) {
  const uint64_t fill = i128_negative(a) ? ~uint64_t{0} : 0;
  if (s == 0) return a;
  if (s >= 64) {
    const unsigned t = s - 64;
    return Int128{t == 0 ? a.hi : (a.hi >> t) | (fill << (64 - t)), fill};
  }
  return Int128{(a.lo >> s) | (a.hi << (64 - s)), (a.hi >> s) | (fill << (64 - s))};
}

// a 2^-s rounded to nearest, ties toward +infinity (add half, shift); a 2^-s exactly for s <= 0.
// As the model's shift_round: 0 for s > 126.
inline constexpr Int128 i128_shift_round(Int128 a, int s) {
  if (s <= 0) return i128_shl(a, static_cast<unsigned>(-s));
  if (s > 126) return Int128{};
  return i128_sar(i128_add(a, i128_shl(Int128{1, 0}, static_cast<unsigned>(s - 1))), static_cast<unsigned>(s));
}

// Index of the most significant set bit of an unsigned 64-bit number (0 for 1); -1 for zero.
inline constexpr int msb_index_u64(uint64_t x) { return x == 0 ? -1 : 63 - __builtin_clzll(x); }

}  // namespace htx::fw
