// The console's texture unpacker (firmware/render texture_pack.cpp), compiled here with the address
// and undefined-behaviour sanitizers, fed a valid packed texture with random damage: it never reads
// past its bytes, and whatever it accepts has texels the upload may read in full.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "htx/render/texture_pack.h"

namespace {

TEST(TexturePackFuzz, DamagedTexturesAreRefusedOrSafe) {
  std::vector<uint16_t> texels(32 * 16);
  for (size_t k = 0; k < texels.size(); ++k) texels[k] = static_cast<uint16_t>(k * 40503u);
  std::vector<uint8_t> good(htx::render::packed_texture_size(5, 4));
  ASSERT_EQ(htx::render::pack_texture(5, 4, 0, texels.data(), good.data(), good.size()), good.size());
  std::mt19937 rng(1205);
  size_t accepted = 0;
  for (int round = 0; round < 20000; ++round) {
    std::vector<uint8_t> bytes = good;
    const int damage = static_cast<int>(rng() % 4);
    for (int k = 0; k <= damage; ++k) {
      // Half the damage in the header, where it matters most.
      const size_t at = rng() % 2 ? rng() % htx::render::kTexturePackHeader : rng() % bytes.size();
      bytes[at] = static_cast<uint8_t>(rng() % 3 ? rng() % 16 : rng());
    }
    if (rng() % 4 == 0) bytes.resize(rng() % (bytes.size() + 16));
    // Exactly the bytes given, in a heap block of their own size (ASan sees a read even one byte
    // past them; operator new's 16-byte alignment keeps the unpacker's word reads aligned).
    const std::unique_ptr<uint8_t[]> exact(new uint8_t[bytes.size()]);
    if (!bytes.empty()) std::memcpy(exact.get(), bytes.data(), bytes.size());
    uint8_t* p = exact.get();
    htx::render::UnpackedTexture t;
    if (htx::render::unpack_texture(p, bytes.size(), 1024, &t)) continue;
    ++accepted;
    ASSERT_GE(t.log2_width, 3);
    ASSERT_LE(t.log2_width, 8);
    ASSERT_GE(t.log2_height, 3);
    ASSERT_LE(t.log2_height, 8);
    ASSERT_LE(t.format, 1);
    ASSERT_LE(1u << (t.log2_width + t.log2_height), 1024u);
    ASSERT_EQ(t.texels, p + htx::render::kTexturePackHeader);
    uint32_t sum = 0;  // every texel byte is inside the buffer
    for (size_t k = 0; k < (size_t{2} << (t.log2_width + t.log2_height)); ++k) sum += t.texels[k];
    ASSERT_LE(sum, 255u * 2048u);
  }
  // Damage to texels, and a header changed to another valid shape of the same size, is accepted.
  EXPECT_GT(accepted, 1000u);
}

}  // namespace
