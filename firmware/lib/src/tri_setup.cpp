#include "htx/fw/tri_setup.h"

namespace htx::fw {

namespace {

int64_t min3(int64_t a, int64_t b, int64_t c) {
  const int64_t m = a < b ? a : b;
  return m < c ? m : c;
}
int64_t max3(int64_t a, int64_t b, int64_t c) {
  const int64_t m = a > b ? a : b;
  return m > c ? m : c;
}
// floor(a / 256) and ceil(a / 256): arithmetic shifts, exact for negative a too.
int64_t floor_div256(int64_t a) { return a >> 8; }
int64_t ceil_div256(int64_t a) { return -((-a) >> 8); }

// |a| < 2^36: make_plane_64's bound on a plane's vertex values.
bool within_plane_64(Int128 a) {
  const uint64_t bias = uint64_t{1} << 36;  // a + 2^36 in [0, 2^37)
  const Int128 b = i128_add(a, u128_from(bias));
  return b.hi == 0 && (b.lo >> 37) == 0;
}

// The reciprocal table's entry for a W-bit mantissa (its k bits below the leading one).
uint32_t table_entry(const RecipSetup& p, uint64_t mantissa) {
  const uint32_t index = static_cast<uint32_t>((mantissa >> (p.width - 1 - p.k)) & ((uint64_t{1} << p.k) - 1));
  return p.table ? p.table[index] : recip_table_entry(p.k, p.g, index);
}

// a b for a signed 64-bit a and an unsigned 64-bit b: one 64 x 64-bit product.
Int128 mul_i64_u64(int64_t a, uint64_t b) {
  const bool neg = a < 0;
  const Int128 m = mul_64x64(neg ? 0 - static_cast<uint64_t>(a) : static_cast<uint64_t>(a), b);
  return neg ? i128_neg(m) : m;
}

}  // namespace

void setup_coverage(const TriangleRecord& rec, int32_t width, int32_t height, CoverageSetup* out) {
  // Filled in place, field by field: a local copy and a default-constructed temporary cost two
  // passes of memset and memcpy over the record, most of the function's time on the rv32im CPU.
  CoverageSetup& s = *out;
  s.rec = rec;
  s.empty = true;
  s.det = 0;
  s.x_lo = 0;
  s.x_hi = -1;
  s.y_lo = 0;
  s.y_hi = -1;
  for (SetupEdge& e : s.edges) e = SetupEdge{};
  VertexRecord* v = s.rec.v;
  const int64_t det = (int64_t{v[1].x} - v[0].x) * (int64_t{v[2].y} - v[0].y) -
                      (int64_t{v[2].x} - v[0].x) * (int64_t{v[1].y} - v[0].y);
  if (det == 0) return;
  if (det < 0) {
    const VertexRecord t = v[1];
    v[1] = v[2];
    v[2] = t;
  }
  s.det = det < 0 ? -det : det;
  for (int k = 0; k < 3; ++k) {
    const VertexRecord& p = v[k];
    const VertexRecord& q = v[(k + 1) % 3];
    const int64_t dx = int64_t{q.x} - p.x, dy = int64_t{q.y} - p.y;
    SetupEdge& e = s.edges[k];
    e.a = -dy;
    e.b = dx;
    e.x0 = p.x;
    e.y0 = p.y;
    // y points down and inside is E > 0: an edge going up is a left edge, a horizontal edge going
    // right a top edge; pixels exactly on those belong to this triangle.
    e.threshold = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
  }
  // Pixel centres 256 i + 128 inside [min, max], clipped to the screen.
  const int64_t xl = ceil_div256(min3(v[0].x, v[1].x, v[2].x) - 128);
  const int64_t xh = floor_div256(max3(v[0].x, v[1].x, v[2].x) - 128);
  const int64_t yl = ceil_div256(min3(v[0].y, v[1].y, v[2].y) - 128);
  const int64_t yh = floor_div256(max3(v[0].y, v[1].y, v[2].y) - 128);
  s.x_lo = static_cast<int32_t>(xl > 0 ? xl : 0);
  s.x_hi = static_cast<int32_t>(xh < width - 1 ? xh : width - 1);
  s.y_lo = static_cast<int32_t>(yl > 0 ? yl : 0);
  s.y_hi = static_cast<int32_t>(yh < height - 1 ? yh : height - 1);
  s.empty = s.x_lo > s.x_hi || s.y_lo > s.y_hi;
}

uint32_t recip_table_entry(uint32_t k, uint32_t g, uint32_t i) {
  // 2 / (a + b) with a + b = 2 + (2i + 1) / 2^k, scaled by 2^(k+g+1); the divisor is odd, so
  // there is never a tie.
  const uint64_t num = uint64_t{1} << (2 * k + g + 2);
  const uint64_t den = (uint64_t{1} << (k + 1)) + 2 * uint64_t{i} + 1;
  return static_cast<uint32_t>((2 * num + den) / (2 * den));
}

void recip_fill_table(uint32_t k, uint32_t g, uint32_t* table) {
  for (uint32_t i = 0; i < (uint32_t{1} << k); ++i) table[i] = recip_table_entry(k, g, i);
}

uint64_t recip_mantissa_64(const RecipSetup& p, uint64_t mantissa) {
  const uint32_t w = p.width;
  const uint32_t entry = table_entry(p, mantissa);
  // m r < 2^(2W+1) and r c < 2^(2W+2): 64 bits hold every step for W <= 30.
  uint64_t r = uint64_t{entry} << (w - (p.k + p.g + 1));
  const uint64_t two = uint64_t{1} << (w + 1), half = uint64_t{1} << (w - 1);
  for (uint32_t s = 0; s < p.steps; ++s) {
    const uint64_t e = (mantissa * r) >> (w - 1);
    const uint64_t c = e < two ? two - e : 0;
    r = (r * c + half) >> w;
  }
  return r;
}

uint64_t recip_mantissa(const RecipSetup& p, uint64_t mantissa) {
  const uint32_t w = p.width;
  if (w <= 30) return recip_mantissa_64(p, mantissa);
  const uint32_t entry = table_entry(p, mantissa);
  Int128 r = i128_shl(u128_from(entry), w - (p.k + p.g + 1));
  const Int128 two = i128_shl(Int128{1, 0}, w + 1);
  const Int128 half = i128_shl(Int128{1, 0}, w - 1);
  for (uint32_t s = 0; s < p.steps; ++s) {
    const Int128 e = i128_sar(i128_mul(u128_from(mantissa), r), w - 1);  // m r, W fraction bits
    const Int128 c = u128_less(e, two) ? i128_sub(two, e) : Int128{};   // 2 - m r
    r = i128_sar(i128_add(i128_mul(r, c), half), w);
  }
  return r.lo;
}

uint64_t recip_normalise(uint64_t x, uint32_t width, int32_t* msb) {
  const int32_t p = msb_index_u64(x);
  *msb = p;
  const int32_t s = p - static_cast<int32_t>(width - 1);
  return s >= 0 ? x >> s : x << -s;
}

RecipResult reciprocal(const RecipSetup& p, uint64_t x) {
  int32_t msb = 0;
  const uint64_t m = recip_normalise(x, p.width, &msb);
  return {recip_mantissa(p, m), static_cast<int32_t>(p.width) + msb};
}

RecipResult reciprocal_64(const RecipSetup& p, uint64_t x) {
  int32_t msb = 0;
  const uint64_t m = recip_normalise(x, p.width, &msb);
  return {recip_mantissa_64(p, m), static_cast<int32_t>(p.width) + msb};
}

void make_plane_64(const CoverageSetup& s, const int64_t values[3], RecipResult inv_det, uint32_t frac_bits,
                   PlaneSetup* out) {
  const VertexRecord* v = s.rec.v;
  const int64_t dx1 = int64_t{v[1].x} - v[0].x, dy1 = int64_t{v[1].y} - v[0].y;
  const int64_t dx2 = int64_t{v[2].x} - v[0].x, dy2 = int64_t{v[2].y} - v[0].y;
  // |da| < 2^37 and |d| < 2^25: each product below 2^62, n below 2^63.
  const int64_t da1 = values[1] - values[0], da2 = values[2] - values[0];
  const int64_t nx = da1 * dy2 - da2 * dy1, ny = da2 * dx1 - da1 * dx2;
  const int32_t shift = inv_det.shift - static_cast<int32_t>(frac_bits);
  out->base = i128_shl(i128_from(values[0]), frac_bits);
  out->gx = i128_shift_round(mul_i64_u64(nx, inv_det.value), shift);
  out->gy = i128_shift_round(mul_i64_u64(ny, inv_det.value), shift);
  out->x0 = v[0].x;
  out->y0 = v[0].y;
}

PlaneSetup make_plane(const CoverageSetup& s, const Int128 values[3], RecipResult inv_det, uint32_t frac_bits) {
  PlaneSetup p;
  if (within_plane_64(values[0]) && within_plane_64(values[1]) && within_plane_64(values[2])) {
    const int64_t v64[3] = {static_cast<int64_t>(values[0].lo), static_cast<int64_t>(values[1].lo),
                            static_cast<int64_t>(values[2].lo)};
    make_plane_64(s, v64, inv_det, frac_bits, &p);
    return p;
  }
  const VertexRecord* v = s.rec.v;
  const Int128 dx1 = i128_from(int64_t{v[1].x} - v[0].x), dy1 = i128_from(int64_t{v[1].y} - v[0].y);
  const Int128 dx2 = i128_from(int64_t{v[2].x} - v[0].x), dy2 = i128_from(int64_t{v[2].y} - v[0].y);
  const Int128 da1 = i128_sub(values[1], values[0]), da2 = i128_sub(values[2], values[0]);
  const Int128 nx = i128_sub(i128_mul(da1, dy2), i128_mul(da2, dy1));
  const Int128 ny = i128_sub(i128_mul(da2, dx1), i128_mul(da1, dx2));
  const int32_t shift = inv_det.shift - static_cast<int32_t>(frac_bits);
  const Int128 r = u128_from(inv_det.value);
  p.base = i128_shl(values[0], frac_bits);
  p.gx = i128_shift_round(i128_mul(nx, r), shift);
  p.gy = i128_shift_round(i128_mul(ny, r), shift);
  p.x0 = v[0].x;
  p.y0 = v[0].y;
  return p;
}

bool divide_fixed_64(const RecipSetup& p, int64_t num, uint64_t den, uint32_t frac_bits, int64_t* out) {
  int32_t msb = 0;
  const uint64_t m = recip_normalise(den, p.width, &msb);
  const int32_t s = msb - static_cast<int32_t>(p.width - 1);
  int64_t n;
  if (s > 0) {
    n = static_cast<int64_t>(i128_shift_round(i128_from(num), s).lo);  // round(num 2^-s)
  } else if (__builtin_mul_overflow(num, int64_t{1} << -s, &n)) {
    return false;
  }
  const Int128 q = mul_i64_u64(n, recip_mantissa_64(p, m));
  *out = static_cast<int64_t>(
      i128_shift_round(q, 2 * static_cast<int32_t>(p.width) - 1 - static_cast<int32_t>(frac_bits)).lo);
  return true;
}

int64_t divide_fixed(const RecipSetup& p, Int128 num, uint64_t den, uint32_t frac_bits) {
  int32_t msb = 0;
  const uint64_t m = recip_normalise(den, p.width, &msb);
  const int32_t s = msb - static_cast<int32_t>(p.width - 1);
  const Int128 n = i128_shift_round(num, s);  // round(num 2^-s), or num 2^-s exactly for s <= 0
  const Int128 q = i128_mul(n, u128_from(recip_mantissa(p, m)));
  return static_cast<int64_t>(i128_shift_round(q, 2 * static_cast<int32_t>(p.width) - 1 - static_cast<int32_t>(frac_bits)).lo);
}

}  // namespace htx::fw
