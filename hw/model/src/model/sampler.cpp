#include "htx/model/sampler.hpp"

namespace htx::model {

namespace {

int64_t floor_shift(int64_t x, unsigned s) { return x >> s; }  // arithmetic shift = floor

}  // namespace

Rgba8 bilinear_blend(Rgba8 c00, Rgba8 c10, Rgba8 c01, Rgba8 c11, unsigned wu, unsigned wv) {
  const unsigned w00 = (256 - wu) * (256 - wv), w10 = wu * (256 - wv), w01 = (256 - wu) * wv, w11 = wu * wv;
  auto mix = [&](uint8_t a, uint8_t b, uint8_t c, uint8_t d) {
    return static_cast<uint8_t>((w00 * a + w10 * b + w01 * c + w11 * d + (1u << 15)) >> 16);
  };
  return {mix(c00.r, c10.r, c01.r, c11.r), mix(c00.g, c10.g, c01.g, c11.g), mix(c00.b, c10.b, c01.b, c11.b),
          mix(c00.a, c10.a, c01.a, c11.a)};
}

Rgba8 linear_blend(Rgba8 a, Rgba8 b, unsigned w) {
  auto mix = [&](uint8_t x, uint8_t y) { return static_cast<uint8_t>((x * (256 - w) + y * w + 128) >> 8); };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b), mix(a.a, b.a)};
}

Rgba8 sample_nearest(const Texture& tex, unsigned level, const TexCoord& c, Wrap wu, Wrap wv) {
  const int64_t ul = floor_shift(c.u, level), vl = floor_shift(c.v, level);
  // ceil(x) - 1 == floor((x_fixed - 1) / 2^f): a coordinate exactly on a texel edge goes down.
  const int64_t i = floor_shift(ul - 1, c.frac_bits), j = floor_shift(vl - 1, c.frac_bits);
  return fetch_texel(tex, level, wrap_index(wu, i, level_log2_width(tex, level)),
                     wrap_index(wv, j, level_log2_height(tex, level)));
}

Rgba8 sample_bilinear(const Texture& tex, unsigned level, const TexCoord& c, Wrap wu, Wrap wv) {
  const unsigned f = c.frac_bits;
  const int64_t half = int64_t{1} << (f - 1);
  const int64_t round = int64_t{1} << (f - 9);  // f >= 9 is guaranteed by the configuration check
  const int64_t pu = floor_shift(floor_shift(c.u, level) - half + round, f - 8);
  const int64_t pv = floor_shift(floor_shift(c.v, level) - half + round, f - 8);
  const int64_t i0 = pu >> 8, j0 = pv >> 8;
  const unsigned wgt_u = static_cast<unsigned>(pu & 255), wgt_v = static_cast<unsigned>(pv & 255);
  const unsigned lw = level_log2_width(tex, level), lh = level_log2_height(tex, level);
  const unsigned x0 = wrap_index(wu, i0, lw), x1 = wrap_index(wu, i0 + 1, lw);
  const unsigned y0 = wrap_index(wv, j0, lh), y1 = wrap_index(wv, j0 + 1, lh);
  return bilinear_blend(fetch_texel(tex, level, x0, y0), fetch_texel(tex, level, x1, y0),
                        fetch_texel(tex, level, x0, y1), fetch_texel(tex, level, x1, y1), wgt_u, wgt_v);
}

Rgba8 sample(const Texture& tex, const SampleRequest& r, unsigned* level_out) {
  switch (r.filter) {
    case Filter::Nearest:
      *level_out = 0;
      return sample_nearest(tex, 0, r.coord, r.wrap_u, r.wrap_v);
    case Filter::Bilinear:
      *level_out = 0;
      return sample_bilinear(tex, 0, r.coord, r.wrap_u, r.wrap_v);
    case Filter::Trilinear: {
      const unsigned top = level_count(tex) - 1;
      const int32_t lod = r.lod < 0 ? 0 : r.lod;
      unsigned l0 = static_cast<unsigned>(lod >> r.lod_frac_bits);
      unsigned w = static_cast<unsigned>(lod & ((1 << r.lod_frac_bits) - 1)) << (8 - r.lod_frac_bits);
      if (l0 >= top) {
        l0 = top;
        w = 0;
      }
      *level_out = l0;
      const Rgba8 a = sample_bilinear(tex, l0, r.coord, r.wrap_u, r.wrap_v);
      if (w == 0) return a;
      const Rgba8 b = sample_bilinear(tex, l0 + 1, r.coord, r.wrap_u, r.wrap_v);
      return linear_blend(a, b, w);
    }
  }
  *level_out = 0;
  return {};
}

}  // namespace htx::model
