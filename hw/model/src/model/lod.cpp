#include "htx/model/lod.hpp"

#include <algorithm>
#include <climits>

namespace htx::model {

uint32_t Log2Unit::table_entry(unsigned index_bits, unsigned out_frac_bits, uint32_t i) {
  // y = 1 + (i + 1/2) / 2^n in [1, 2) with 62 fraction bits; each squaring yields one bit of log2(y).
  constexpr unsigned kFrac = 62;
  u128 y = (static_cast<u128>(1) << kFrac) +
           ((static_cast<u128>(2 * i + 1)) << (kFrac - index_bits - 1));
  const unsigned bits = out_frac_bits + 8;  // extra bits, then round
  uint64_t acc = 0;
  for (unsigned b = 0; b < bits; ++b) {
    y = (y * y) >> kFrac;
    acc <<= 1;
    if (y >= (static_cast<u128>(2) << kFrac)) {
      acc |= 1;
      y >>= 1;
    }
  }
  return static_cast<uint32_t>((acc + (uint64_t{1} << 7)) >> 8);
}

Log2Unit::Log2Unit(unsigned index_bits, unsigned out_frac_bits)
    : index_bits_(index_bits), out_frac_bits_(out_frac_bits), table_(size_t{1} << index_bits) {
  for (uint32_t i = 0; i < table_.size(); ++i) table_[i] = table_entry(index_bits, out_frac_bits, i);
}

int64_t Log2Unit::log2(u128 x) const {
  const int p = msb_index(x);
  const u128 below = x - (static_cast<u128>(1) << p);
  const uint32_t idx = static_cast<uint32_t>(
      p >= static_cast<int>(index_bits_) ? below >> (p - static_cast<int>(index_bits_))
                                         : below << (static_cast<int>(index_bits_) - p));
  return (static_cast<int64_t>(p) << out_frac_bits_) + table_[idx];
}

int lod_gradient_shift(const i128 (&gradients)[6], unsigned bits) {
  i128 big = 0;
  for (i128 g : gradients) big = std::max(big, abs128(g));
  return std::max(0, msb_index(static_cast<u128>(big)) + 2 - static_cast<int>(bits));
}

int32_t compute_lod(const Log2Unit& unit, const LodInputs& in, unsigned lod_frac_bits) {
  const unsigned f = in.tex_frac_bits;
  // Numerators of the four derivatives, each (G * 2^f - coord * Gq): per subpixel, scaled by
  // 2^f * q. The common factor 256 / (2^f q) is applied in the log domain.
  const i128 nux = mul_checked(in.gux, static_cast<i128>(1) << f) - mul_checked(in.u, in.gqx);
  const i128 nvx = mul_checked(in.gvx, static_cast<i128>(1) << f) - mul_checked(in.v, in.gqx);
  const i128 nuy = mul_checked(in.guy, static_cast<i128>(1) << f) - mul_checked(in.u, in.gqy);
  const i128 nvy = mul_checked(in.gvy, static_cast<i128>(1) << f) - mul_checked(in.v, in.gqy);
  const u128 big = static_cast<u128>(std::max({abs128(nux), abs128(nvx), abs128(nuy), abs128(nvy)}));
  if (big == 0) return INT32_MIN;
  // Keep 31 significant bits so the squared lengths fit 64 bits; the dropped low bits are far below
  // the LOD's precision.
  const int s = std::max(0, msb_index(big) - 30);
  auto sq = [s](i128 a) {
    const i128 r = a >> s;
    return static_cast<u128>(r * r);
  };
  const u128 lx = sq(nux) + sq(nvx), ly = sq(nuy) + sq(nvy);
  const u128 len2 = std::max(lx, ly);
  const unsigned of = unit.out_frac_bits();
  // log2 rho = log2(len2)/2 + s + grad_shift + 8 - f - log2(q)
  const int64_t l = (unit.log2(len2) >> 1) + (static_cast<int64_t>(s + in.grad_shift + 8) << of) -
                    (static_cast<int64_t>(f) << of) - unit.log2(static_cast<u128>(in.q));
  const unsigned drop = of - lod_frac_bits;
  const int64_t r = drop ? (l + (int64_t{1} << (drop - 1))) >> drop : l;
  return static_cast<int32_t>(std::clamp<int64_t>(r, INT32_MIN + 1, INT32_MAX));
}

}  // namespace htx::model
