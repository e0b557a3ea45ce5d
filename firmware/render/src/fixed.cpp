#include "htx/render/fixed.h"

namespace htx::render {

namespace {

// Seeds of the reciprocal: entry i ~ 2^24 / (256 + i + 1/2), the reciprocal of the midpoint of
// the i-th of 256 intervals of the normalised mantissa in [1, 2), scaled into [2^15, 2^16].
struct SeedTable {
  uint16_t v[256];
  constexpr SeedTable() : v() {
    for (uint32_t i = 0; i < 256; ++i) v[i] = static_cast<uint16_t>(((uint32_t{1} << 25) + (256 + i)) / (2 * (256 + i) + 1));
  }
};
constexpr SeedTable kSeeds;

}  // namespace

Reciprocal reciprocal(uint32_t x) {
  Reciprocal r;
  if (x == 0) return r;
  r.lz = clz32_inline(x);
  const uint32_t m = x << r.lz;  // in [2^31, 2^32): m / 2^32 in [1/2, 1)
  if (m == 0x80000000u) {        // a power of two: 2^63 / m = 2^32 does not fit; 2^31 at the next exponent
    r.mant = 0x80000000u;
    r.lz += 1;
    return r;
  }
  // Seed with 9 correct bits from the table, then two Newton-Raphson steps (9 -> 18 -> 31 bits).
  uint32_t y = static_cast<uint32_t>(kSeeds.v[(m >> 23) & 0xFFu]) << 16;
  for (int step = 0; step < 2; ++step) {
    // e = m * y / 2^32 ~ 2^31 (x*y ~ 1 in Q31); y' = y * (2 - x*y). Newton approaches 1/x from
    // below, but the two truncated products can leave y a unit above it (callers clamp).
    const uint32_t e = static_cast<uint32_t>((static_cast<uint64_t>(m) * y) >> 32);
    const uint32_t t = 0u - e;  // 2^32 - e
    const uint64_t next = (static_cast<uint64_t>(y) * t) >> 31;
    y = next > 0xFFFFFFFFull ? 0xFFFFFFFFu : static_cast<uint32_t>(next);
  }
  r.mant = y;
  return r;
}

}  // namespace htx::render
