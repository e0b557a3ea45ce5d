// Texture unit: texel formats, mip chain, wrap modes, nearest tie rule, bilinear and trilinear.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "htx/model/sampler.hpp"
#include "htx/model/texture.hpp"

namespace htx {
namespace {

TEST(TexelFormat, ChannelQuantisationRoundsToNearest) {
  for (unsigned bits : {4u, 5u, 6u, 8u})
    for (unsigned c = 0; c < 256; ++c) {
      const unsigned x = c * ((1u << bits) - 1);
      const unsigned want = (2 * x + 255) / 510;  // round(x / 255), never a tie (255 is odd)
      EXPECT_EQ(quantise_channel(c, bits), want) << "bits=" << bits << " c=" << c;
    }
}

TEST(TexelFormat, BitReplication) {
  EXPECT_EQ(decode_texel(TexFormat::RGB565, 0xFFFF), (Rgba8{255, 255, 255, 255}));
  EXPECT_EQ(decode_texel(TexFormat::RGB565, 0x0000), (Rgba8{0, 0, 0, 255}));
  // r = 10000b -> 10000100b, g = 100000b -> 10000010b, b = 00001b -> 00001000b
  EXPECT_EQ(decode_texel(TexFormat::RGB565, (0x10u << 11) | (0x20u << 5) | 0x01u), (Rgba8{0x84, 0x82, 0x08, 255}));
  EXPECT_EQ(decode_texel(TexFormat::RGBA4444, 0x9A5F), (Rgba8{0x99, 0xAA, 0x55, 0xFF}));
  EXPECT_EQ(decode_texel(TexFormat::RGBA8888, 0x80402010u), (Rgba8{0x10, 0x20, 0x40, 0x80}));
}

TEST(TexelFormat, EncodeDecodeRoundTripsEveryPackedValue) {
  for (uint32_t t = 0; t < 65536; ++t) {
    EXPECT_EQ(encode_texel(TexFormat::RGB565, decode_texel(TexFormat::RGB565, t)), t);
    EXPECT_EQ(encode_texel(TexFormat::RGBA4444, decode_texel(TexFormat::RGBA4444, t)), t);
  }
  for (uint32_t t : {0u, 0xFFFFFFFFu, 0x12345678u, 0x80FF00A5u})
    EXPECT_EQ(encode_texel(TexFormat::RGBA8888, decode_texel(TexFormat::RGBA8888, t)), t);
  // 8-bit -> packed -> 8-bit stays within half a step of the packed format.
  for (unsigned c = 0; c < 256; ++c) {
    const Rgba8 in{static_cast<uint8_t>(c), static_cast<uint8_t>(c), static_cast<uint8_t>(c), static_cast<uint8_t>(c)};
    const Rgba8 o5 = decode_texel(TexFormat::RGB565, encode_texel(TexFormat::RGB565, in));
    const Rgba8 o4 = decode_texel(TexFormat::RGBA4444, encode_texel(TexFormat::RGBA4444, in));
    EXPECT_LE(std::abs(int(o5.r) - int(c)), 5) << c;
    EXPECT_LE(std::abs(int(o5.g) - int(c)), 3) << c;
    EXPECT_LE(std::abs(int(o4.a) - int(c)), 9) << c;
  }
}

std::vector<uint8_t> pattern(unsigned w, unsigned h) {
  std::vector<uint8_t> px(static_cast<size_t>(w) * h * 4);
  uint32_t s = 12345;
  for (auto& b : px) {
    s = s * 1103515245u + 12345u;
    b = static_cast<uint8_t>(s >> 16);
  }
  return px;
}

TEST(MipChain, LevelsAreRoundedBoxFiltersOfTheLevelAbove) {
  const auto px = pattern(16, 8);
  const Texture t = make_texture(TexFormat::RGBA8888, 4, 3, px);
  ASSERT_EQ(t.levels.size(), 5u);  // 16x8, 8x4, 4x2, 2x1, 1x1
  const unsigned sizes[5][2] = {{16, 8}, {8, 4}, {4, 2}, {2, 1}, {1, 1}};
  for (unsigned l = 0; l < 5; ++l) EXPECT_EQ(t.levels[l].size(), size_t{sizes[l][0]} * sizes[l][1]) << l;
  for (unsigned l = 1; l < 5; ++l) {
    const unsigned w = sizes[l][0], h = sizes[l][1], pw = sizes[l - 1][0], ph = sizes[l - 1][1];
    const unsigned fx = pw / w, fy = ph / h;
    for (unsigned j = 0; j < h; ++j)
      for (unsigned i = 0; i < w; ++i) {
        unsigned sum[4] = {};
        for (unsigned dy = 0; dy < fy; ++dy)
          for (unsigned dx = 0; dx < fx; ++dx) {
            const Rgba8 c = fetch_texel(t, l - 1, i * fx + dx, j * fy + dy);
            sum[0] += c.r;
            sum[1] += c.g;
            sum[2] += c.b;
            sum[3] += c.a;
          }
        const unsigned n = fx * fy;
        const Rgba8 want{static_cast<uint8_t>((sum[0] + n / 2) / n), static_cast<uint8_t>((sum[1] + n / 2) / n),
                         static_cast<uint8_t>((sum[2] + n / 2) / n), static_cast<uint8_t>((sum[3] + n / 2) / n)};
        EXPECT_EQ(fetch_texel(t, l, i, j), want) << "level " << l << " texel " << i << "," << j;
      }
  }
}

TEST(MipChain, RoundingOfTheBox) {
  // 8x8 RGBA8888 with a 2x2 block 0,0,0,1 -> 0 (1+2 >> 2) and 1,1,1,0 -> 1 (3+2 >> 2), 0,0,1,1 -> 1.
  std::vector<uint8_t> px(8 * 8 * 4, 0);
  auto set = [&](unsigned x, unsigned y, uint8_t v) { px[(y * 8 + x) * 4] = v; };
  set(1, 1, 1);
  set(2, 0, 1), set(3, 0, 1), set(2, 1, 1);
  set(4, 1, 1), set(5, 1, 1);
  const Texture t = make_texture(TexFormat::RGBA8888, 3, 3, px);
  EXPECT_EQ(fetch_texel(t, 1, 0, 0).r, 0);
  EXPECT_EQ(fetch_texel(t, 1, 1, 0).r, 1);
  EXPECT_EQ(fetch_texel(t, 1, 2, 0).r, 1);
}

TEST(MipChain, RejectsBadSizes) {
  EXPECT_THROW(make_texture(TexFormat::RGB565, 2, 3, std::vector<uint8_t>(4 * 8 * 4)), std::invalid_argument);
  EXPECT_THROW(make_texture(TexFormat::RGB565, 9, 3, std::vector<uint8_t>(512 * 8 * 4)), std::invalid_argument);
  EXPECT_THROW(make_texture(TexFormat::RGB565, 3, 3, std::vector<uint8_t>(10)), std::invalid_argument);
}

TEST(Wrap, RepeatClampMirror) {
  const int64_t in[] = {-17, -9, -8, -1, 0, 1, 7, 8, 9, 15, 16, 17};
  const unsigned rep[] = {7, 7, 0, 7, 0, 1, 7, 0, 1, 7, 0, 1};
  const unsigned clp[] = {0, 0, 0, 0, 0, 1, 7, 7, 7, 7, 7, 7};
  const unsigned mir[] = {0, 7, 7, 0, 0, 1, 7, 7, 6, 0, 0, 1};
  for (size_t k = 0; k < std::size(in); ++k) {
    EXPECT_EQ(wrap_index(Wrap::Repeat, in[k], 3), rep[k]) << in[k];
    EXPECT_EQ(wrap_index(Wrap::Clamp, in[k], 3), clp[k]) << in[k];
    EXPECT_EQ(wrap_index(Wrap::Mirror, in[k], 3), mir[k]) << in[k];
  }
}

// An 8x8 RGBA8888 texture whose texel (i, j) has r = i, g = j.
Texture index_texture() {
  std::vector<uint8_t> px(8 * 8 * 4);
  for (unsigned j = 0; j < 8; ++j)
    for (unsigned i = 0; i < 8; ++i) {
      px[(j * 8 + i) * 4 + 0] = static_cast<uint8_t>(i * 16);
      px[(j * 8 + i) * 4 + 1] = static_cast<uint8_t>(j * 16);
      px[(j * 8 + i) * 4 + 3] = 255;
    }
  return make_texture(TexFormat::RGBA8888, 3, 3, px);
}

TEST(Nearest, ExactTiesGoLowerLeft) {
  const Texture t = index_texture();
  constexpr unsigned f = 16;
  auto at = [&](int64_t u, int64_t v) { return model::sample_nearest(t, 0, {u, v, f}, Wrap::Repeat, Wrap::Repeat); };
  // u = 3.0 is the edge between texels 2 and 3: goes to 2; one step above goes to 3.
  EXPECT_EQ(at(3 << f, 5 << f), (Rgba8{32, 64, 0, 255}));
  EXPECT_EQ(at((3 << f) + 1, (5 << f) + 1), (Rgba8{48, 80, 0, 255}));
  EXPECT_EQ(at((3 << f) - 1, (5 << f) - 1), (Rgba8{32, 64, 0, 255}));
  // Texel centres.
  EXPECT_EQ(at((3 << f) + (1 << (f - 1)), (6 << f) + (1 << (f - 1))), (Rgba8{48, 96, 0, 255}));
  // At level 1 texel i covers level-0 (2i, 2i+2]: u = 4.0 is a level-1 edge and goes to texel 1.
  EXPECT_EQ(model::sample_nearest(t, 1, {4 << f, 4 << f, f}, Wrap::Repeat, Wrap::Repeat),
            fetch_texel(t, 1, 1, 1));
  // u = 0 wraps to the last texel under repeat.
  EXPECT_EQ(at(0, 1 << (f - 1)), (Rgba8{112, 0, 0, 255}));
}

TEST(Bilinear, EightBitWeights) {
  const Texture t = index_texture();
  constexpr unsigned f = 16;
  auto at = [&](int64_t u, int64_t v) {
    return model::sample_bilinear(t, 0, {u, v, f}, Wrap::Clamp, Wrap::Clamp);
  };
  // At a texel centre the weight is 0: exactly that texel.
  EXPECT_EQ(at((2 << f) + (1 << (f - 1)), (4 << f) + (1 << (f - 1))), (Rgba8{32, 64, 0, 255}));
  // Half-way between centres of texels 2 and 3 (u = 3.0): weight 128, (32*128 + 48*128 + 128) >> 8 = 40.
  EXPECT_EQ(at(3 << f, (4 << f) + (1 << (f - 1))).r, 40);
  // A quarter (weight 64): (32*192 + 48*64 + 128) >> 8 = 36.
  EXPECT_EQ(at((2 << f) + (3 << (f - 2)), (4 << f) + (1 << (f - 1))).r, 36);
  // Weight rounding to 1/256: 1/512 texel past the centre rounds up to weight 1.
  const Rgba8 c = model::bilinear_blend({0, 0, 0, 0}, {255, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1, 0);
  EXPECT_EQ(c.r, 1);  // (255 * 256 + 2^15) >> 16
  EXPECT_EQ(at((2 << f) + (1 << (f - 1)) + (1 << (f - 9)), (4 << f) + (1 << (f - 1))).r, 32);  // (32*255+48+128)>>8
  EXPECT_EQ(at((2 << f) + (1 << (f - 1)) + (1 << (f - 8)) * 16, (4 << f) + (1 << (f - 1))).r, 33);
  // Both weights 128 on a 2x2 of r = 2,3 and g = 4,5: centre of the four.
  const Rgba8 m = at(3 << f, 5 << f);
  EXPECT_EQ(m.r, 40);
  EXPECT_EQ(m.g, 72);
}

TEST(Trilinear, BlendsTwoLevelsByTheLodFraction) {
  const Texture t = index_texture();
  constexpr unsigned f = 16;
  model::SampleRequest r;
  r.coord = {(3 << f) + 1234, (5 << f) + 777, f};
  r.filter = Filter::Trilinear;
  r.lod_frac_bits = 8;
  unsigned level = 99;
  r.lod = 0;
  const Rgba8 l0 = model::sample(t, r, &level);
  EXPECT_EQ(level, 0u);
  EXPECT_EQ(l0, model::sample_bilinear(t, 0, r.coord, Wrap::Repeat, Wrap::Repeat));
  r.lod = 256 + 64;  // level 1 + 1/4
  const Rgba8 mix = model::sample(t, r, &level);
  EXPECT_EQ(level, 1u);
  EXPECT_EQ(mix, model::linear_blend(model::sample_bilinear(t, 1, r.coord, Wrap::Repeat, Wrap::Repeat),
                                     model::sample_bilinear(t, 2, r.coord, Wrap::Repeat, Wrap::Repeat), 64));
  r.lod = 100 * 256;  // beyond the chain: the last level
  model::sample(t, r, &level);
  EXPECT_EQ(level, 3u);
}

}  // namespace
}  // namespace htx
