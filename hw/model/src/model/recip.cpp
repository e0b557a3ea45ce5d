#include "htx/model/recip.hpp"

#include <stdexcept>

#include "htx/fw/tri_setup.h"

namespace htx::model {

// The firmware's (firmware/lib tri_setup.h): one table for the model and the firmware.
uint32_t recip_table_entry(unsigned k, unsigned g, uint32_t i) { return fw::recip_table_entry(k, g, i); }

uint64_t recip_mantissa(const RecipParams& p, uint64_t mantissa) {
  const unsigned w = p.width;
  const uint64_t index = (mantissa >> (w - 1 - p.k)) & ((uint64_t{1} << p.k) - 1);
  u128 r = static_cast<u128>(recip_table_entry(p.k, p.g, static_cast<uint32_t>(index))) << (w - (p.k + p.g + 1));
  for (unsigned s = 0; s < p.steps; ++s) {
    const u128 e = (static_cast<u128>(mantissa) * r) >> (w - 1);  // m * r, W fraction bits
    const u128 two = static_cast<u128>(1) << (w + 1);
    const u128 c = e >= two ? 0 : two - e;  // 2 - m*r
    r = (r * c + (static_cast<u128>(1) << (w - 1))) >> w;
  }
  return static_cast<uint64_t>(r);
}

uint64_t normalise(u128 x, unsigned width, int* msb) {
  const int p = msb_index(x);
  if (p < 0) throw std::logic_error("reciprocal of zero");
  *msb = p;
  const int s = p - static_cast<int>(width - 1);
  return static_cast<uint64_t>(s >= 0 ? x >> s : x << -s);
}

Reciprocal reciprocal(const RecipParams& p, u128 x) {
  int msb = 0;
  const uint64_t m = normalise(x, p.width, &msb);
  return {recip_mantissa(p, m), static_cast<int>(p.width) + msb};
}

int64_t divide_fixed(const RecipParams& p, i128 num, i128 den, unsigned frac_bits) {
  if (den < 1) throw std::logic_error("divider: denominator must be positive");
  int msb = 0;
  const uint64_t m = normalise(static_cast<u128>(den), p.width, &msb);
  const int s = msb - static_cast<int>(p.width - 1);
  const i128 n = s > 0 ? shift_round(num, s) : mul_checked(num, static_cast<i128>(1) << -s);
  const uint64_t r = recip_mantissa(p, m);
  return static_cast<int64_t>(shift_round(mul_checked(n, static_cast<i128>(r)),
                                          2 * static_cast<int>(p.width) - 1 - static_cast<int>(frac_bits)));
}

}  // namespace htx::model
