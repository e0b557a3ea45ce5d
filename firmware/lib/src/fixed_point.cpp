#include "htx/fw/fixed_point.h"

namespace htx::fw {

int64_t round_nearest(double x) {
  if (!(x == x)) return 0;  // NaN
  constexpr double kLimit = 4611686018427387904.0;  // 2^62
  if (x >= kLimit) return INT64_C(4611686018427387904);
  if (x <= -kLimit) return -INT64_C(4611686018427387904);
  // Beyond 2^52 every double is an integer. Below, floor(x) and x - floor(x) are exact, where
  // x + 0.5 itself could round (0.49999999999999994 + 0.5 is 1.0, and 2^52 + 1 + 0.5 is 2^52 + 2).
  constexpr double kIntegral = 4503599627370496.0;  // 2^52
  if (x >= kIntegral || x <= -kIntegral) return static_cast<int64_t>(x);
  int64_t t = static_cast<int64_t>(x);  // truncates toward zero
  if (static_cast<double>(t) > x) --t;  // floor for negative non-integers
  return x - static_cast<double>(t) >= 0.5 ? t + 1 : t;
}

int normalising_exponent(double x) {
  if (!(x > 0) || x > 1.7e308) return 0;
  int e = 0;
  while (x >= 1.0) {
    x *= 0.5;
    --e;
  }
  while (x < 0.5) {
    x *= 2.0;
    ++e;
  }
  return e;
}

double scale_by_pow2(double x, int e) {
  while (e > 0) {
    x *= 2.0;
    --e;
  }
  while (e < 0) {
    x *= 0.5;
    ++e;
  }
  return x;
}

int count_leading_zeros64(uint64_t x) {
  if (x == 0) return 64;
  int n = 0;
  while (!(x & (UINT64_C(1) << 63))) {
    x <<= 1;
    ++n;
  }
  return n;
}

}  // namespace htx::fw
