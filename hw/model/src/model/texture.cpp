#include "htx/model/texture.hpp"

#include <stdexcept>
#include <string>

namespace htx {

namespace {

unsigned widen(unsigned v, unsigned bits) {
  // Bit replication: the top bits repeat into the low bits.
  if (bits == 8) return v;
  unsigned out = v << (8 - bits);
  for (int shift = static_cast<int>(8 - 2 * bits); shift > -static_cast<int>(bits); shift -= static_cast<int>(bits))
    out |= shift >= 0 ? v << shift : v >> -shift;
  return out & 0xFF;
}

}  // namespace

unsigned quantise_channel(unsigned c8, unsigned bits) {
  // round(c * (2^n - 1) / 255) without a divider: x/255 ~ (x + 128 + ((x + 128) >> 8)) >> 8,
  // exact rounding for every x in 0..255*255 (checked exhaustively in tests/model).
  const unsigned x = (c8 & 0xFF) * ((1u << bits) - 1) + 128;
  return (x + (x >> 8)) >> 8;
}

uint32_t encode_texel(TexFormat format, Rgba8 c) {
  switch (format) {
    case TexFormat::RGB565:
      return (quantise_channel(c.r, 5) << 11) | (quantise_channel(c.g, 6) << 5) | quantise_channel(c.b, 5);
    case TexFormat::RGBA4444:
      return (quantise_channel(c.r, 4) << 12) | (quantise_channel(c.g, 4) << 8) |
             (quantise_channel(c.b, 4) << 4) | quantise_channel(c.a, 4);
    case TexFormat::RGBA8888:
      return static_cast<uint32_t>(c.r) | (static_cast<uint32_t>(c.g) << 8) |
             (static_cast<uint32_t>(c.b) << 16) | (static_cast<uint32_t>(c.a) << 24);
  }
  throw std::invalid_argument("encode_texel: unknown texture format");
}

Rgba8 decode_texel(TexFormat format, uint32_t t) {
  Rgba8 c;
  switch (format) {
    case TexFormat::RGB565:
      c.r = static_cast<uint8_t>(widen((t >> 11) & 31, 5));
      c.g = static_cast<uint8_t>(widen((t >> 5) & 63, 6));
      c.b = static_cast<uint8_t>(widen(t & 31, 5));
      c.a = 255;
      return c;
    case TexFormat::RGBA4444:
      c.r = static_cast<uint8_t>(widen((t >> 12) & 15, 4));
      c.g = static_cast<uint8_t>(widen((t >> 8) & 15, 4));
      c.b = static_cast<uint8_t>(widen((t >> 4) & 15, 4));
      c.a = static_cast<uint8_t>(widen(t & 15, 4));
      return c;
    case TexFormat::RGBA8888:
      c.r = static_cast<uint8_t>(t);
      c.g = static_cast<uint8_t>(t >> 8);
      c.b = static_cast<uint8_t>(t >> 16);
      c.a = static_cast<uint8_t>(t >> 24);
      return c;
  }
  throw std::invalid_argument("decode_texel: unknown texture format");
}

unsigned level_log2_width(const Texture& tex, unsigned level) {
  return level >= tex.log2_width ? 0 : tex.log2_width - level;
}
unsigned level_log2_height(const Texture& tex, unsigned level) {
  return level >= tex.log2_height ? 0 : tex.log2_height - level;
}
unsigned level_count(const Texture& tex) {
  return (tex.log2_width > tex.log2_height ? tex.log2_width : tex.log2_height) + 1;
}

Rgba8 fetch_texel(const Texture& tex, unsigned level, unsigned i, unsigned j) {
  const unsigned lw = level_log2_width(tex, level);
  return decode_texel(tex.format, tex.levels[level][(static_cast<size_t>(j) << lw) + i]);
}

Texture make_texture(TexFormat format, unsigned log2_width, unsigned log2_height,
                     std::span<const uint8_t> rgba8) {
  if (log2_width < kMinTexLog2 || log2_width > kMaxTexLog2 || log2_height < kMinTexLog2 ||
      log2_height > kMaxTexLog2)
    throw std::invalid_argument("make_texture: size 2^" + std::to_string(log2_width) + " x 2^" +
                                std::to_string(log2_height) + " outside 8..256 texels");
  const size_t w = size_t{1} << log2_width, h = size_t{1} << log2_height;
  if (rgba8.size() != w * h * 4)
    throw std::invalid_argument("make_texture: " + std::to_string(rgba8.size()) + " bytes for " +
                                std::to_string(w) + "x" + std::to_string(h) + " RGBA8 texels");
  Texture tex;
  tex.format = format;
  tex.log2_width = log2_width;
  tex.log2_height = log2_height;
  const unsigned n = level_count(tex);
  tex.levels.resize(n);
  std::vector<Rgba8> cur(w * h);
  for (size_t k = 0; k < w * h; ++k) {
    const Rgba8 c{rgba8[4 * k], rgba8[4 * k + 1], rgba8[4 * k + 2], rgba8[4 * k + 3]};
    tex.levels[0].push_back(encode_texel(format, c));
    cur[k] = decode_texel(format, tex.levels[0].back());
  }
  size_t cw = w, ch = h;
  for (unsigned level = 1; level < n; ++level) {
    const size_t nw = cw > 1 ? cw / 2 : 1, nh = ch > 1 ? ch / 2 : 1;
    const size_t fx = cw / nw, fy = ch / nh;  // 1 or 2 texels per axis in the box
    const unsigned count = static_cast<unsigned>(fx * fy);
    const unsigned round = count / 2;
    const unsigned shift = count == 4 ? 2 : (count == 2 ? 1 : 0);
    std::vector<Rgba8> next(nw * nh);
    for (size_t j = 0; j < nh; ++j)
      for (size_t i = 0; i < nw; ++i) {
        unsigned s[4] = {0, 0, 0, 0};
        for (size_t dy = 0; dy < fy; ++dy)
          for (size_t dx = 0; dx < fx; ++dx) {
            const Rgba8& c = cur[(j * fy + dy) * cw + i * fx + dx];
            s[0] += c.r;
            s[1] += c.g;
            s[2] += c.b;
            s[3] += c.a;
          }
        const Rgba8 box{static_cast<uint8_t>((s[0] + round) >> shift), static_cast<uint8_t>((s[1] + round) >> shift),
                        static_cast<uint8_t>((s[2] + round) >> shift), static_cast<uint8_t>((s[3] + round) >> shift)};
        const uint32_t t = encode_texel(format, box);
        tex.levels[level].push_back(t);
        next[j * nw + i] = decode_texel(format, t);
      }
    cur.swap(next);
    cw = nw;
    ch = nh;
  }
  return tex;
}

unsigned wrap_index(Wrap wrap, int64_t i, unsigned log2_size) {
  const int64_t size = int64_t{1} << log2_size;
  switch (wrap) {
    case Wrap::Repeat:
      return static_cast<unsigned>(i & (size - 1));
    case Wrap::Clamp:
      return static_cast<unsigned>(i < 0 ? 0 : (i >= size ? size - 1 : i));
    case Wrap::Mirror: {
      const int64_t m = i & (2 * size - 1);  // position in the mirrored period
      return static_cast<unsigned>(m < size ? m : 2 * size - 1 - m);
    }
  }
  throw std::invalid_argument("wrap_index: unknown wrap mode");
}

}  // namespace htx
