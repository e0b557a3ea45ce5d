// Fixed-point arithmetic of the geometry stage (docs/firmware.md, "Number formats").
// Q16.16: int32 with 16 fraction bits; products go through 64-bit intermediates and are rounded to
// nearest, ties toward +infinity (the rounding rule of htx::fw). Freestanding C++17.
#pragma once

#include <stdint.h>

namespace htx::render {

inline constexpr int kFracBits = 16;
inline constexpr int32_t kOne = int32_t{1} << kFracBits;

// floor(v / 2^s + 1/2) for s >= 1 (arithmetic shift).
inline int64_t round_shift(int64_t v, int s) { return (v + (int64_t{1} << (s - 1))) >> s; }

// The same for an unsigned 32-bit v and any s >= 0 (s = 0: v), in 32-bit arithmetic: the shifted
// value plus the last bit shifted out, which cannot overflow as v + 2^(s - 1) can.
inline uint32_t round_shift_u32(uint32_t v, int s) {
  if (s == 0) return v;
  if (s > 32) return 0;  // v + 2^(s - 1) < 2^s
  const uint32_t half_bit = (v >> (s - 1)) & 1u;
  return (s == 32 ? 0u : v >> s) + half_bit;
}

// v * 2^s, wrapping as the CPU's shift does: a left shift of a negative value is undefined in
// C++17 (UBSan reports it), a shift of its bits is not.
inline int32_t shift_left(int32_t v, int s) { return static_cast<int32_t>(static_cast<uint32_t>(v) << s); }
inline int64_t shift_left(int64_t v, int s) { return static_cast<int64_t>(static_cast<uint64_t>(v) << s); }

// Saturates to the int32 range.
inline int32_t saturate32(int64_t v) {
  return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : static_cast<int32_t>(v));
}

// Q16.16 product, rounded.
inline int32_t mul_q16(int32_t a, int32_t b) {
  return saturate32(round_shift(static_cast<int64_t>(a) * b, kFracBits));
}

// Number of leading zeros; 32 for zero.
inline int clz32(uint32_t x) { return x ? __builtin_clz(x) : 32; }
// The same without a library call (rv32im has no clz instruction), for x != 0.
inline int clz32_inline(uint32_t x) {
  int n = 0;
  if (!(x & 0xFFFF0000u)) { n += 16; x <<= 16; }
  if (!(x & 0xFF000000u)) { n += 8; x <<= 8; }
  if (!(x & 0xF0000000u)) { n += 4; x <<= 4; }
  if (!(x & 0xC0000000u)) { n += 2; x <<= 2; }
  if (!(x & 0x80000000u)) n += 1;
  return n;
}

// 1/x for x > 0 as mant * 2^-(63 - lz): mant in [2^31, 2^32) is 1/m for the normalised
// m = x * 2^lz in [2^31, 2^32), with 32 significant bits (relative error below 2^-31).
struct Reciprocal {
  uint32_t mant = 0;
  int lz = 0;
};

// A 256-entry seed table, then two Newton-Raphson steps (docs/firmware.md).
// x = 0 gives {0, 0} (callers never divide by zero: w > 0 after clipping).
Reciprocal reciprocal(uint32_t x);

}  // namespace htx::render
