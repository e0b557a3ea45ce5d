// The texture unit's sampling datapath (docs/model.md, "Texture unit"): fixed-point texel
// coordinates in, 8-bit RGBA out. Nearest, bilinear with 8-bit weights, trilinear between two levels.
#pragma once

#include <cstdint>

#include "htx/model/texture.hpp"
#include "htx/model/types.hpp"

namespace htx::model {

// A texel coordinate in level-0 texels with `frac_bits` fractional bits (u = s * width).
struct TexCoord {
  int64_t u = 0, v = 0;
  unsigned frac_bits = 16;
};

struct SampleRequest {
  TexCoord coord;
  Filter filter = Filter::Nearest;
  Wrap wrap_u = Wrap::Repeat, wrap_v = Wrap::Repeat;
  int32_t lod = 0;           // trilinear only: LOD with lod_frac_bits fractional bits, >= 0
  unsigned lod_frac_bits = 8;
};

// Nearest: texel ceil(uL) - 1 at level L (ties to the lower index), uL = u / 2^L truncated to the
// coordinate's fraction bits.
Rgba8 sample_nearest(const Texture& tex, unsigned level, const TexCoord& c, Wrap wu, Wrap wv);
// Bilinear at level L: p = uL - 1/2 rounded to 1/256, i0 = floor(p), weight = the 8 fraction bits.
Rgba8 sample_bilinear(const Texture& tex, unsigned level, const TexCoord& c, Wrap wu, Wrap wv);
// Full request; *level_out receives the (finer) level sampled.
Rgba8 sample(const Texture& tex, const SampleRequest& r, unsigned* level_out);

// The 8-bit bilinear blend of four texels with weights wu, wv in 0..255 (weight of the +1 texel):
// per channel ((256-wu)(256-wv) c00 + wu (256-wv) c10 + (256-wu) wv c01 + wu wv c11 + 2^15) >> 16.
Rgba8 bilinear_blend(Rgba8 c00, Rgba8 c10, Rgba8 c01, Rgba8 c11, unsigned wu, unsigned wv);
// (a (256 - w) + b w + 128) >> 8 per channel.
Rgba8 linear_blend(Rgba8 a, Rgba8 b, unsigned w);

}  // namespace htx::model
