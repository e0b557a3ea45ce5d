#include "htx/render/fixed.h"

namespace htx::render {

Reciprocal reciprocal(uint32_t x) {
  Reciprocal r;
  if (x == 0) return r;
  r.lz = clz32(x);
  const uint32_t m = x << r.lz;  // in [2^31, 2^32): m / 2^32 in [1/2, 1)
  if (m == 0x80000000u) {  // a power of two: 2^63 / m = 2^32 does not fit; 2^31 at the next exponent
    r.mant = 0x80000000u;
    r.lz += 1;
    return r;
  }
  // Estimate y = 2^63 / m (in (2^31, 2^32)) from the top 16 bits of m: 17 bits are right.
  const uint32_t top = (m >> 16) + 1;  // rounded up, so the estimate is below the true value
  uint32_t y = (0xFFFFFFFFu / top) << 15;
  for (int step = 0; step < 2; ++step) {
    // e = m * y / 2^32 ~ 2^31 (x*y ~ 1 in Q31); y' = y * (2 - x*y).
    const uint32_t e = static_cast<uint32_t>((static_cast<uint64_t>(m) * y) >> 32);
    const uint64_t t = 0x100000000ull - e;
    const uint64_t next = (static_cast<uint64_t>(y) * t) >> 31;
    y = next > 0xFFFFFFFFull ? 0xFFFFFFFFu : static_cast<uint32_t>(next);
  }
  r.mant = y;
  return r;
}

}  // namespace htx::render
