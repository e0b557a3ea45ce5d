// AutoNum: the number type of AUTO's bounds and costs (auto_select.cpp, docs/auto.md "Arithmetic").
// A binary floating-point value m * 2^e with a 32-bit mantissa normalised to 2^30 <= |m| < 2^31 (or
// m = 0), computed with integer operations only, each result truncated (not rounded): identical on
// the host and on the rv32im CPU, where AUTO's work costs 2.5 times fewer cycles than with the
// soft-float library (which handles rounding modes, infinities, NaNs and subnormals that AUTO never
// needs). Its precision (31 bits) is above float's (24 bits); it has no infinities or NaNs: a
// division by zero gives a value of 2^(2^20) with the dividend's sign, and the exponent's range is
// never reached from float inputs. Freestanding C++17.
#pragma once

#include <stdint.h>

// The small operations are always inlined: at -Os the calls cost as much as the work.
#define HTX_AUTO_NUM_INLINE __attribute__((always_inline)) inline

namespace htx::fw {

struct AutoNum {
  int32_t m = 0;  // 0, or 2^30 <= |m| < 2^31
  int32_t e = 0;  // value = m * 2^e
};

namespace auto_num_detail {

// Leading zeros of a non-zero 32-bit value (a binary search: the CPU has no such instruction, and
// the library's __clzsi2 is a call).
HTX_AUTO_NUM_INLINE int leading_zeros(uint32_t v) {
  int n = 0;
  if (!(v >> 16)) n += 16, v <<= 16;
  if (!(v >> 24)) n += 8, v <<= 8;
  if (!(v >> 28)) n += 4, v <<= 4;
  if (!(v >> 30)) n += 2, v <<= 2;
  if (!(v >> 31)) n += 1;
  return n;
}

HTX_AUTO_NUM_INLINE uint32_t magnitude(int32_t m) { return m < 0 ? 0u - static_cast<uint32_t>(m) : static_cast<uint32_t>(m); }

// sign * mag * 2^e for 0 < mag < 2^31, normalised by a left shift.
HTX_AUTO_NUM_INLINE AutoNum make_small(bool negative, uint32_t mag, int32_t e) {
  // (most sums need no shift or one)
  const int shift = (mag >> 29) ? !(mag >> 30) : leading_zeros(mag) - 1;
  const int32_t m = static_cast<int32_t>(mag << shift);
  return {negative ? -m : m, e - shift};
}

// sign * mag * 2^e for 2^30 <= mag < 2^32: at most one right shift.
HTX_AUTO_NUM_INLINE AutoNum make_large(bool negative, uint32_t mag, int32_t e) {
  if (mag >> 31) {
    mag >>= 1;
    ++e;
  }
  const int32_t m = static_cast<int32_t>(mag);
  return {negative ? -m : m, e};
}

// The high word of a 32 x 32-bit product (one mulhu on the CPU).
HTX_AUTO_NUM_INLINE uint32_t mul_high(uint32_t a, uint32_t b) {
  return static_cast<uint32_t>((static_cast<uint64_t>(a) * b) >> 32);
}

// 2^61 / y for 2^30 <= y < 2^31, within a few units of 2^-29 relative, as R in (2^30, 2^31): a
// linear first guess (48 - 32 y') / 17 for y' = y / 2^31 in [1/2, 1) (within 1/17), then three
// Newton steps R += R (1 - y' R), each squaring the error. Integer multiplies only: the CPU's
// divider takes 37 clocks a word and a 64-bit quotient needs a library call.
HTX_AUTO_NUM_INLINE uint32_t reciprocal(uint32_t y) {
  const uint32_t yy = y << 1;                                   // y' in Q32
  uint32_t r = 3031741621u - mul_high(2021161081u, yy);         // (48 - 32 y') / 17, Q30
  for (int i = 0; i < 3; ++i) {
    const int32_t err = static_cast<int32_t>((uint32_t{1} << 30) - mul_high(yy, r));  // 1 - y' R, Q30
    r += static_cast<uint32_t>((static_cast<int64_t>(err) * r) >> 30);
  }
  return r > 0x7FFFFFFFu ? 0x7FFFFFFFu : r;
}

}  // namespace auto_num_detail

inline AutoNum num_from_int(int32_t v) {
  if (v == 0) return {};
  const uint32_t mag = auto_num_detail::magnitude(v);
  if (mag >> 31) return {-(int32_t{1} << 30), 1};  // -2^31
  return auto_num_detail::make_small(v < 0, mag, 0);
}

// 2^k.
HTX_AUTO_NUM_INLINE AutoNum num_pow2(int32_t k) { return {int32_t{1} << 30, k - 30}; }

// A finite float, exactly (the caller checks finiteness: an infinity or NaN reads as a huge value).
inline AutoNum num_from_float(float f) {
  uint32_t bits;
  __builtin_memcpy(&bits, &f, sizeof bits);
  const int32_t biased = static_cast<int32_t>((bits >> 23) & 0xFFu);
  const uint32_t frac = bits & 0x7FFFFFu;
  const bool negative = (bits >> 31) != 0;
  if (biased == 0) return frac == 0 ? AutoNum{} : auto_num_detail::make_small(negative, frac, -149);  // subnormal
  const int32_t m = static_cast<int32_t>((frac | 0x800000u) << 7);
  return {negative ? -m : m, biased - 157};
}

// The smallest float >= a (toward plus infinity): reported bounds and costs never understate.
inline float num_to_float_up(AutoNum a) {
  uint32_t bits = 0;
  if (a.m != 0) {
    const bool negative = a.m < 0;
    const uint32_t mag = auto_num_detail::magnitude(a.m);  // 2^30 <= mag < 2^31
    uint32_t top = mag >> 7;                                 // 24 bits
    const bool inexact = (mag & 0x7Fu) != 0;
    int32_t biased = a.e + 7 + 23 + 127;
    if (inexact && !negative && ++top == (1u << 24)) {
      top >>= 1;
      ++biased;
    }
    if (biased >= 255) {
      bits = negative ? 0xFF7FFFFFu : 0x7F800000u;  // -FLT_MAX, +infinity
    } else if (biased <= 0) {
      bits = negative ? 0x80000000u : 0x00800000u;  // -0, FLT_MIN (no subnormals needed here)
    } else {
      bits = (negative ? 0x80000000u : 0u) | (static_cast<uint32_t>(biased) << 23) | (top & 0x7FFFFFu);
    }
  }
  float f;
  __builtin_memcpy(&f, &bits, sizeof f);
  return f;
}

HTX_AUTO_NUM_INLINE AutoNum operator-(AutoNum a) { return {-a.m, a.e}; }

inline AutoNum operator+(AutoNum a, AutoNum b) {
  if (a.m == 0) return b;
  if (b.m == 0) return a;
  if (a.e < b.e) {
    const AutoNum t = a;
    a = b;
    b = t;
  }
  // Both as multiples of 2^(a.e + 1), b shifted right (arithmetic: toward minus infinity, by less
  // than a unit). Each half is below 2^30 in magnitude (-2^30 at most), so the sum fits 32 bits:
  // |sum| <= 2^31, 2^31 only for two mantissas of -(2^31 - 1), which the shifts round to -2^30
  // each: one right shift then, otherwise left shifts only. (32-bit arithmetic: on the CPU a
  // 64-bit sum and its magnitude cost a third of the operation.)
  const int32_t d = a.e - b.e;
  if (d > 31) return a;
  const int32_t sum = (a.m >> 1) + ((b.m >> 1) >> d);
  if (sum == 0) return {};
  const uint32_t mag = sum < 0 ? 0u - static_cast<uint32_t>(sum) : static_cast<uint32_t>(sum);
  if (mag >> 31) return {-(int32_t{1} << 30), a.e + 2};  // only -2^31
  return auto_num_detail::make_small(sum < 0, mag, a.e + 1);
}

inline AutoNum operator-(AutoNum a, AutoNum b) { return a + (-b); }

inline AutoNum operator*(AutoNum a, AutoNum b) {
  if (a.m == 0 || b.m == 0) return {};
  // (2|a|)(2|b|) / 2^32 is in [2^30, 2^32).
  const uint32_t p = auto_num_detail::mul_high(auto_num_detail::magnitude(a.m) << 1, auto_num_detail::magnitude(b.m) << 1);
  return auto_num_detail::make_large((a.m < 0) != (b.m < 0), p, a.e + b.e + 30);
}

inline AutoNum operator/(AutoNum a, AutoNum b) {
  if (b.m == 0) return {a.m < 0 ? -(int32_t{1} << 30) : int32_t{1} << 30, int32_t{1} << 20};
  if (a.m == 0) return {};
  // A power of two divides exactly (its reciprocal, 2^31, is the one the Newton steps cannot hold).
  if (auto_num_detail::magnitude(b.m) == (uint32_t{1} << 30)) return {b.m < 0 ? -a.m : a.m, a.e - b.e - 30};
  // |a| / |b| = |a| R 2^-61 with R = 2^61 / |b|; (2|a|)(2R) / 2^32 is in (2^30, 2^32).
  const uint32_t r = auto_num_detail::reciprocal(auto_num_detail::magnitude(b.m));
  const uint32_t p = auto_num_detail::mul_high(auto_num_detail::magnitude(a.m) << 1, r << 1);
  return auto_num_detail::make_large((a.m < 0) != (b.m < 0), p, a.e - b.e - 31);
}

// a * 2^k, exactly.
HTX_AUTO_NUM_INLINE AutoNum num_scale(AutoNum a, int32_t k) { return a.m == 0 ? a : AutoNum{a.m, a.e + k}; }

// a < b. Of different signs, or with a zero among them, the mantissas' signs decide (a zero's
// mantissa is 0); of one sign, both normalised, the exponent decides (reversed when negative), then
// the mantissa. Compares are AUTO's most frequent operation: no three-way result to test again.
HTX_AUTO_NUM_INLINE bool operator<(AutoNum a, AutoNum b) {
  if ((a.m ^ b.m) < 0 || a.m == 0 || b.m == 0 || a.e == b.e) return a.m < b.m;
  return (a.e < b.e) == (a.m > 0);
}
HTX_AUTO_NUM_INLINE bool operator>(AutoNum a, AutoNum b) { return b < a; }
HTX_AUTO_NUM_INLINE bool operator<=(AutoNum a, AutoNum b) { return !(b < a); }
HTX_AUTO_NUM_INLINE bool operator>=(AutoNum a, AutoNum b) { return !(a < b); }
HTX_AUTO_NUM_INLINE bool operator==(AutoNum a, AutoNum b) { return a.m == b.m && (a.m == 0 || a.e == b.e); }

HTX_AUTO_NUM_INLINE AutoNum num_abs(AutoNum a) { return a.m < 0 ? -a : a; }
HTX_AUTO_NUM_INLINE AutoNum num_min(AutoNum a, AutoNum b) { return b < a ? b : a; }
HTX_AUTO_NUM_INLINE AutoNum num_max(AutoNum a, AutoNum b) { return a < b ? b : a; }

}  // namespace htx::fw

#undef HTX_AUTO_NUM_INLINE
