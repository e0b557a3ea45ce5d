// Wide integers for the model: the datapaths of `full` exceed 64 bits (docs/model.md lists every
// width). Products are checked: a result outside 127 bits means a width assumption is broken, which
// is a model bug, reported as std::logic_error rather than silently wrapped.
#pragma once

#include <cstdint>
#include <stdexcept>

namespace htx::model {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

inline i128 mul_checked(i128 a, i128 b) {
  i128 r;
  if (__builtin_mul_overflow(a, b, &r)) throw std::logic_error("model datapath overflow in a product");
  return r;
}

inline i128 add_checked(i128 a, i128 b) {
  i128 r;
  if (__builtin_add_overflow(a, b, &r)) throw std::logic_error("model datapath overflow in a sum");
  return r;
}

// a * 2^-s rounded to nearest, ties toward +infinity (add half, arithmetic shift). s may be <= 0.
inline i128 shift_round(i128 a, int s) {
  if (s <= 0) {
    if (s < -100) throw std::logic_error("model shift out of range");
    return mul_checked(a, static_cast<i128>(1) << -s);
  }
  if (s > 126) return 0;
  return (a + (static_cast<i128>(1) << (s - 1))) >> s;
}

// floor(a / b) and ceil(a / b) for b != 0.
inline i128 floor_div(i128 a, i128 b) {
  i128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}
inline i128 ceil_div(i128 a, i128 b) { return -floor_div(-a, b); }

inline i128 abs128(i128 a) { return a < 0 ? -a : a; }

// Index of the most significant set bit (0 for 1); -1 for zero.
inline int msb_index(u128 x) {
  if (x == 0) return -1;
  const uint64_t hi = static_cast<uint64_t>(x >> 64);
  if (hi) return 127 - __builtin_clzll(hi);
  return 63 - __builtin_clzll(static_cast<uint64_t>(x));
}

}  // namespace htx::model
