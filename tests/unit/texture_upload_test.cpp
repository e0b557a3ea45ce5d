// The texel formats and the mip chain of firmware/lib against the model (hw/model texture.cpp,
// make_texture), and the texture driver (hal/include/htx/hal/texture.h) with the upload of
// firmware/render over the FakeBus: every level lands at the documented layout (docs/texture.md),
// the descriptor reads as documented, bad input is refused without a write.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "htx/fw/console_packet.h"
#include "htx/fw/mip_chain.h"
#include "htx/fw/texel.h"
#include "htx/hal/sim/fake_bus.hpp"
#include "htx/hal/texture.h"
#include "htx/model/texture.hpp"
#include "htx/render/texture_pack.h"
#include "htx/render/texture_upload.h"
#include "doc_texture_layout.hpp"

namespace {

using htx::test::doc_word;

using htx::hal::sim::FakeBus;

// The CAPS of the `full` configuration's unit (8 slots, every format, the whole 1 MiB window),
// which texture_check reads (it answers 0 on a FakeBus that does not set it: no slots at all).
void poke_full_caps(FakeBus& bus) {
  bus.poke(HTX_TEXTURE_BASE + TEXTURE_CAPS_Offset,
           (8u << TEXTURE_CAPS_SLOTS_Pos) | (7u << TEXTURE_CAPS_FORMATS_Pos) | (16u << TEXTURE_CAPS_BLOCK_BITS_Pos));
}

// Writes in the bus's log (a refused upload reads CAPS, and writes nothing).
size_t writes_logged(const FakeBus& bus) {
  size_t n = 0;
  for (const FakeBus::Access& a : bus.log()) n += a.write;
  return n;
}
using htx::hal::sim::ScopedBus;

uint32_t pack(const htx::Rgba8& c) {
  return uint32_t{c.r} | (uint32_t{c.g} << 8) | (uint32_t{c.b} << 16) | (uint32_t{c.a} << 24);
}

std::vector<uint32_t> random_image(std::mt19937& rng, unsigned lw, unsigned lh) {
  std::vector<uint32_t> img(size_t{1} << (lw + lh));
  for (uint32_t& p : img) p = rng();
  return img;
}

std::vector<uint8_t> bytes_of(const std::vector<uint32_t>& img) {
  std::vector<uint8_t> b;
  for (uint32_t p : img)
    for (int k = 0; k < 4; ++k) b.push_back(static_cast<uint8_t>(p >> (8 * k)));
  return b;
}

constexpr htx::TexFormat kFormats[] = {htx::TexFormat::RGB565, htx::TexFormat::RGBA4444, htx::TexFormat::RGBA8888};

TEST(Texel, EncodeAndDecodeEqualTheModelForEveryChannelValue) {
  for (const htx::TexFormat f : kFormats) {
    const uint8_t fmt = static_cast<uint8_t>(f);
    for (uint32_t c = 0; c < 256; ++c) {
      const htx::Rgba8 rgba{static_cast<uint8_t>(c), static_cast<uint8_t>(255 - c), static_cast<uint8_t>(c * 7),
                            static_cast<uint8_t>(c * 13)};
      ASSERT_EQ(htx::fw::encode_texel(fmt, pack(rgba)), htx::encode_texel(f, rgba)) << int(fmt) << " " << c;
    }
    const uint32_t n = f == htx::TexFormat::RGBA8888 ? 70000 : 65536;
    std::mt19937 rng(5);
    for (uint32_t t = 0; t < n; ++t) {
      const uint32_t texel = f == htx::TexFormat::RGBA8888 ? rng() : t;
      ASSERT_EQ(htx::fw::decode_texel(fmt, texel), pack(htx::decode_texel(f, texel))) << int(fmt) << " " << texel;
    }
  }
  EXPECT_EQ(htx::fw::encode_texel(3, 0xFFFFFFFFu), 0u);  // unknown format: documented 0
  EXPECT_EQ(htx::fw::decode_texel(3, 0xFFFFu), 0u);
}

// The whole chain, level by level, equals make_texture's for every format and shape.
TEST(MipChain, EqualsTheModelChainForEveryFormatAndShape) {
  std::mt19937 rng(11);
  const unsigned sizes[][2] = {{3, 3}, {6, 6}, {8, 3}, {3, 8}, {5, 7}, {8, 8}};
  for (const htx::TexFormat f : kFormats)
    for (const auto& sz : sizes) {
      const unsigned lw = sz[0], lh = sz[1];
      const std::vector<uint32_t> img = random_image(rng, lw, lh);
      const htx::Texture model = htx::make_texture(f, lw, lh, bytes_of(img));
      const unsigned levels = htx::fw::mip_level_count(lw, lh);
      ASSERT_EQ(levels, model.levels.size());
      std::vector<uint32_t> level(size_t{1} << (lw + lh - 2));
      for (unsigned l = 1; l < levels; ++l) {
        const unsigned aw = htx::fw::mip_level_log2(lw, l - 1), ah = htx::fw::mip_level_log2(lh, l - 1);
        if (l == 1)
          htx::fw::mip_next_level(static_cast<uint8_t>(f), img.data(), htx::fw::kMipSourceRgba8, aw, ah, level.data());
        else
          htx::fw::mip_next_level(static_cast<uint8_t>(f), level.data(), htx::fw::kMipSourceTexels, aw, ah,
                                  level.data());  // in place
        const size_t count = size_t{1} << (htx::fw::mip_level_log2(lw, l) + htx::fw::mip_level_log2(lh, l));
        ASSERT_EQ(model.levels[l].size(), count);
        for (size_t k = 0; k < count; ++k)
          ASSERT_EQ(level[k], model.levels[l][k]) << "format " << int(f) << " " << lw << "x" << lh << " level " << l
                                                  << " texel " << k;
      }
      // The levels are not trivially equal: a random image has distinct texels at level 1.
      EXPECT_NE(model.levels[1][0], model.levels[1][1]);
    }
}

TEST(TextureDriver, UploadWritesEveryLevelAtTheDocumentedLayoutThenTheDescriptor) {
  std::mt19937 rng(3);
  struct Case {
    htx::TexFormat f;
    unsigned lw, lh, slot, base;
  };
  for (const Case c : {Case{htx::TexFormat::RGB565, 6, 6, 0, 0}, Case{htx::TexFormat::RGBA4444, 5, 3, 3, 1366},
                       Case{htx::TexFormat::RGBA8888, 3, 7, 7, 40000}}) {
    FakeBus bus;
    ScopedBus attach(bus);
    poke_full_caps(bus);
    const std::vector<uint32_t> img = random_image(rng, c.lw, c.lh);
    const htx::Texture model = htx::make_texture(c.f, c.lw, c.lh, bytes_of(img));
    std::vector<uint32_t> scratch(htx::render::texture_upload_scratch_words(c.lw, c.lh));
    const htx::render::TextureImage tex{img.data(), static_cast<uint8_t>(c.lw), static_cast<uint8_t>(c.lh),
                                        static_cast<uint8_t>(c.f)};
    ASSERT_EQ(htx::render::upload_texture(c.slot, c.base, tex, scratch.data(), static_cast<uint32_t>(scratch.size()),
                                          100),
              htx::render::kUploadOk);
    // The descriptor is the last write: BASE, LOG2_WIDTH, LOG2_HEIGHT, FORMAT of hw/regs/texture.json.
    const uint32_t desc = HTX_TEXTURE_BASE + TEXTURE_TEX0_Offset + 4 * c.slot;
    const std::vector<uint32_t> d = bus.writes_to(desc);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0], c.base | (c.lw << 16) | (c.lh << 20) | (static_cast<uint32_t>(c.f) << 24));
    EXPECT_TRUE(bus.log().back().write);
    EXPECT_EQ(bus.log().back().addr, desc);
    // Exactly one write per texel of the chain, each inside the chain's blocks.
    size_t window_writes = 0;
    const uint32_t chain_end = htx::hal::kTexWindowBase + 16 * (c.base + htx::hal::texture_chain_blocks(c.lw, c.lh));
    for (const FakeBus::Access& a : bus.log())
      if (a.write && a.addr >= htx::hal::kTexWindowBase) {
        ++window_writes;
        EXPECT_GE(a.addr, htx::hal::kTexWindowBase + 16 * c.base);
        EXPECT_LT(a.addr, chain_end);
      }
    size_t texels = 0;
    for (unsigned l = 0; l < model.levels.size(); ++l) {
      const uint32_t w = 1u << htx::fw::mip_level_log2(c.lw, l), h = 1u << htx::fw::mip_level_log2(c.lh, l);
      for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
          const uint32_t addr = htx::hal::kTexWindowBase + 4 * doc_word(c.base, c.lw, c.lh, l, i, j);
          ASSERT_EQ(bus.peek(addr), model.levels[l][j * w + i]) << "level " << l << " (" << i << ", " << j << ")";
          ASSERT_EQ(htx::hal::texture_read_texel(c.base, c.lw, c.lh, l, i, j), model.levels[l][j * w + i]);
          ++texels;
        }
    }
    EXPECT_EQ(window_writes, texels);
  }
  // 64x64: 1366 blocks (docs/texture.md).
  EXPECT_EQ(htx::hal::texture_chain_blocks(6, 6), 1366u);
}

TEST(TextureDriver, BadInputIsRefusedWithoutAWrite) {
  FakeBus bus;
  ScopedBus attach(bus);
  poke_full_caps(bus);
  std::vector<uint32_t> img(64 * 64, 0x80808080u), scratch(32 * 32);
  htx::render::TextureImage tex{img.data(), 6, 6, 0};
  const auto upload = [&](uint32_t slot, uint32_t base, uint32_t scratch_words, htx::hal::TextureStatus* why) {
    return htx::render::upload_texture(slot, base, tex, scratch.data(), scratch_words, 10, why);
  };
  htx::hal::TextureStatus why = htx::hal::kTextureOk;
  EXPECT_EQ(upload(8, 0, 1024, &why), htx::render::kUploadBadTexture);
  EXPECT_EQ(why, htx::hal::kTextureBadSlot);
  EXPECT_EQ(upload(0, 65536, 1024, &why), htx::render::kUploadBadTexture);
  EXPECT_EQ(why, htx::hal::kTextureBadBase);
  EXPECT_EQ(upload(0, 65536 - 1000, 1024, &why), htx::render::kUploadBadTexture);  // runs past the 1 MiB window
  EXPECT_EQ(why, htx::hal::kTextureTooLarge);
  EXPECT_EQ(upload(0, 0, 1023, &why), htx::render::kUploadScratchTooSmall);
  tex.format = 3;
  EXPECT_EQ(upload(0, 0, 1024, &why), htx::render::kUploadBadTexture);
  EXPECT_EQ(why, htx::hal::kTextureBadFormat);
  tex.format = 0;
  tex.log2_width = 9;
  EXPECT_EQ(upload(0, 0, 1 << 16, &why), htx::render::kUploadBadTexture);
  EXPECT_EQ(why, htx::hal::kTextureBadSize);
  tex.log2_width = 2;
  EXPECT_EQ(upload(0, 0, 1 << 16, &why), htx::render::kUploadBadTexture);
  EXPECT_EQ(writes_logged(bus), 0u);

  // A unit that never goes idle: the chain is written, the descriptor is not, and the wait ends.
  tex.log2_width = 6;
  bus.poke(HTX_TEXTURE_BASE + TEXTURE_STATUS_Offset, TEXTURE_STATUS_BUSY_Msk);
  EXPECT_EQ(upload(0, 0, 1024, &why), htx::render::kUploadTimeout);
  EXPECT_EQ(why, htx::hal::kTextureTimeout);
  EXPECT_EQ(bus.reads_of(HTX_TEXTURE_BASE + TEXTURE_STATUS_Offset), 10u);
  EXPECT_TRUE(bus.writes_to(HTX_TEXTURE_BASE + TEXTURE_TEX0_Offset).empty());
}

TEST(TextureDriver, CapsStatusAndCounters) {
  FakeBus bus;
  ScopedBus attach(bus);
  poke_full_caps(bus);
  bus.poke(HTX_TEXTURE_BASE + TEXTURE_CAPS_Offset, 0x3u | (0x3u << 4) | (4u << 8) | (10u << 16) | (16u << 24));
  const htx::hal::TextureCaps caps = htx::hal::texture_caps();
  EXPECT_EQ(caps.formats, 3u);
  EXPECT_EQ(caps.filters, 3u);
  EXPECT_FALSE(caps.counters);
  EXPECT_EQ(caps.slots, 4u);
  EXPECT_EQ(caps.block_bits, 10u);
  EXPECT_EQ(caps.texel_bits, 16u);
  EXPECT_FALSE(caps.window_read);
  bus.poke(HTX_TEXTURE_BASE + TEXTURE_CAPS_Offset, 0x3u | TEXTURE_CAPS_WINDOW_READ_Msk);
  EXPECT_TRUE(htx::hal::texture_caps().window_read);
  bus.poke(HTX_TEXTURE_BASE + TEXTURE_STATUS_Offset, TEXTURE_STATUS_ERR_FILTER_Msk);
  EXPECT_EQ(htx::hal::texture_errors(), TEXTURE_STATUS_ERR_FILTER_Msk);
  htx::hal::texture_clear_errors();
  EXPECT_EQ(bus.writes_to(HTX_TEXTURE_BASE + TEXTURE_STATUS_Offset),
            std::vector<uint32_t>{TEXTURE_STATUS_ERR_FORMAT_Msk | TEXTURE_STATUS_ERR_FILTER_Msk});
  htx::hal::texture_reset_counters();
  EXPECT_EQ(bus.writes_to(HTX_TEXTURE_BASE + TEXTURE_CNT_RESET_Offset), std::vector<uint32_t>{1u});
  bus.poke(HTX_TEXTURE_BASE + TEXTURE_CNT_SAMPLES_Offset, 1234);
  EXPECT_EQ(htx::hal::texture_samples(), 1234u);
}

// The texel path (a console's texture upload) writes exactly what the image path writes for the
// image its texels decode to, write for write, though it builds level 1 in place over its input.
TEST(TextureDriver, Texels16UploadWritesWhatTheImageUploadWrites) {
  std::mt19937 rng(17);
  const unsigned sizes[][2] = {{3, 3}, {5, 5}, {7, 3}, {3, 7}, {5, 4}, {8, 3}};
  for (const htx::TexFormat f : {htx::TexFormat::RGB565, htx::TexFormat::RGBA4444})
    for (const auto& sz : sizes) {
      const unsigned lw = sz[0], lh = sz[1];
      const uint8_t fmt = static_cast<uint8_t>(f);
      std::vector<uint32_t> texels(size_t{1} << (lw + lh)), rgba(texels.size());
      for (size_t k = 0; k < texels.size(); ++k) {
        texels[k] = rng() & 0xFFFFu;
        rgba[k] = htx::fw::decode_texel(fmt, texels[k]);
      }
      FakeBus image_bus;
      poke_full_caps(image_bus);
      {
        ScopedBus attach(image_bus);
        std::vector<uint32_t> scratch(htx::render::texture_upload_scratch_words(lw, lh));
        const htx::render::TextureImage tex{rgba.data(), static_cast<uint8_t>(lw), static_cast<uint8_t>(lh), fmt};
        ASSERT_EQ(htx::render::upload_texture(1, 700, tex, scratch.data(), static_cast<uint32_t>(scratch.size()), 10),
                  htx::render::kUploadOk);
      }
      // Two bytes a texel, little-endian, in word storage as the console's staging buffer.
      std::vector<uint32_t> words((texels.size() + 1) / 2);
      auto* bytes = reinterpret_cast<uint8_t*>(words.data());
      for (size_t k = 0; k < texels.size(); ++k) {
        bytes[2 * k] = static_cast<uint8_t>(texels[k]);
        bytes[2 * k + 1] = static_cast<uint8_t>(texels[k] >> 8);
      }
      FakeBus texel_bus;
      poke_full_caps(texel_bus);
      {
        ScopedBus attach(texel_bus);
        ASSERT_EQ(htx::render::upload_texture_texels16(1, 700, static_cast<uint8_t>(lw), static_cast<uint8_t>(lh), fmt,
                                                       bytes, 10),
                  htx::render::kUploadOk);
      }
      ASSERT_EQ(texel_bus.log().size(), image_bus.log().size()) << lw << "x" << lh;
      for (size_t k = 0; k < image_bus.log().size(); ++k) {
        ASSERT_EQ(texel_bus.log()[k].write, image_bus.log()[k].write) << k;
        ASSERT_EQ(texel_bus.log()[k].addr, image_bus.log()[k].addr) << k;
        if (image_bus.log()[k].write) {
          ASSERT_EQ(texel_bus.log()[k].value, image_bus.log()[k].value) << k;
        }
      }
    }
}

TEST(TextureDriver, Texels16RefusesOtherFormatsWithoutAWrite) {
  FakeBus bus;
  ScopedBus attach(bus);
  poke_full_caps(bus);
  std::vector<uint32_t> words(32);
  auto* bytes = reinterpret_cast<uint8_t*>(words.data());
  htx::hal::TextureStatus why = htx::hal::kTextureBadSlot;
  EXPECT_EQ(htx::render::upload_texture_texels16(0, 0, 3, 3, 2, bytes, 10, &why), htx::render::kUploadBadTexture);
  EXPECT_EQ(why, htx::hal::kTextureOk);  // the driver takes RGBA8888; this path does not
  EXPECT_EQ(htx::render::upload_texture_texels16(0, 0, 2, 3, 0, bytes, 10, &why), htx::render::kUploadBadTexture);
  EXPECT_EQ(why, htx::hal::kTextureBadSize);
  EXPECT_EQ(htx::render::upload_texture_texels16(0, 0, 3, 3, 0, nullptr, 10), htx::render::kUploadBadTexture);
  EXPECT_EQ(writes_logged(bus), 0u);
}

std::vector<uint8_t> packed_texture(uint8_t lw, uint8_t lh, uint8_t format, std::vector<uint16_t>* texels_out = nullptr) {
  std::vector<uint16_t> texels(size_t{1} << (lw + lh));
  for (size_t k = 0; k < texels.size(); ++k) texels[k] = static_cast<uint16_t>(k * 2654435761u >> 7);
  std::vector<uint8_t> out(htx::render::packed_texture_size(lw, lh));
  EXPECT_EQ(htx::render::pack_texture(lw, lh, format, texels.data(), out.data(), out.size()), out.size());
  if (texels_out) *texels_out = texels;
  return out;
}

TEST(TexturePack, RoundTripReadsTheTexelsInPlace) {
  std::vector<uint16_t> texels;
  std::vector<uint8_t> bytes = packed_texture(5, 4, 1, &texels);
  EXPECT_EQ(bytes.size(), 12u + 2u * 512u);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "HTXT");
  htx::render::UnpackedTexture t;
  ASSERT_EQ(htx::render::unpack_texture(bytes.data(), bytes.size(), 1024, &t), nullptr);
  EXPECT_EQ(t.log2_width, 5);
  EXPECT_EQ(t.log2_height, 4);
  EXPECT_EQ(t.format, 1);
  EXPECT_EQ(t.texels, bytes.data() + htx::render::kTexturePackHeader);
  for (size_t k = 0; k < texels.size(); ++k) ASSERT_EQ(htx::fw::get_le16(t.texels + 2 * k), texels[k]) << k;
}

TEST(TexturePack, EveryBadFieldIsRefusedWithItsOwnMessage) {
  const std::vector<uint8_t> good = packed_texture(3, 3, 0);
  const auto why = [](std::vector<uint8_t> b, uint32_t max_texels = 1024) {
    htx::render::UnpackedTexture t;
    const char* w = htx::render::unpack_texture(b.data(), b.size(), max_texels, &t);
    return std::string(w ? w : "ok");
  };
  EXPECT_EQ(why(good), "ok");
  auto with = [&good](size_t at, uint8_t v) {
    std::vector<uint8_t> b = good;
    b[at] = v;
    return b;
  };
  EXPECT_EQ(why(with(0, 'X')), "not a packed texture (no HTXT)");
  EXPECT_EQ(why(with(4, 2)), "an unknown version");
  EXPECT_EQ(why(with(6, 2)), "a side is not 8 to 256 texels");
  EXPECT_EQ(why(with(7, 9)), "a side is not 8 to 256 texels");
  EXPECT_EQ(why(with(8, 2)), "the format is not RGB565 or RGBA4444");
  EXPECT_EQ(why(with(11, 1)), "reserved bytes are not zero");
  EXPECT_EQ(why(good, 32), "more texels than the console takes");
  EXPECT_EQ(why(with(6, 4)), "the size does not match its sides");  // 16 x 8 announced, 8 x 8 sent
  for (size_t n = 0; n < good.size(); ++n) {
    const std::vector<uint8_t> cut(good.begin(), good.begin() + static_cast<long>(n));
    EXPECT_NE(why(cut), "ok") << n;
  }
  std::vector<uint8_t> longer = good;
  longer.push_back(0);
  EXPECT_EQ(why(longer), "the size does not match its sides");
  std::vector<uint8_t> out(good.size());
  std::vector<uint16_t> texels(64);
  EXPECT_EQ(htx::render::pack_texture(3, 3, 0, texels.data(), out.data(), out.size() - 1), 0u);  // no room
  EXPECT_EQ(htx::render::pack_texture(3, 3, 2, texels.data(), out.data(), out.size()), 0u);      // RGBA8888
  EXPECT_EQ(htx::render::pack_texture(9, 3, 0, texels.data(), out.data(), out.size()), 0u);
}

}  // namespace
