// The GPU's two bus ports (docs/gpu.md): the register port decodes RASTER and TEXTURE and answers
// anything else with an error; the memory port reaches the framebuffer, depth and texture windows;
// a texture uploaded through the window reads back word for word in the documented layout; one
// colour page.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "htx/model/texture.hpp"
#include "htx/rtl/gpu_sim.hpp"
#include "htx/rtl/texture_layout.hpp"
#include "../../unit/doc_texture_layout.hpp"
#include "htx_regs.h"

namespace htx {
namespace {

using htx::test::doc_word;
using htx::test::kDocTextureWindow;

using rtl::GpuSim;

class GpuBus : public ::testing::TestWithParam<const char*> {};

TEST_P(GpuBus, RegisterPortDecodesBothBlocksAndRejectsTheRest) {
  GpuSim sim(GetParam());
  const uint32_t caps = sim.read_reg(HTX_TEXTURE_BASE + offsetof(HTX_TEXTURE_Type, CAPS));
  const bool full = std::string(GetParam()) == "full";
  EXPECT_EQ((caps & TEXTURE_CAPS_SLOTS_Msk) >> TEXTURE_CAPS_SLOTS_Pos, full ? 8u : 4u);
  EXPECT_EQ((caps & TEXTURE_CAPS_FORMATS_Msk) >> TEXTURE_CAPS_FORMATS_Pos, full ? 7u : 3u);
  EXPECT_EQ(sim.texture_blocks(), full ? 1u << 15 : 1u << 12);
  EXPECT_NE(caps & TEXTURE_CAPS_WINDOW_READ_Msk, 0u);  // the Verilated models read texture memory back
  // RASTER answers its registers: FB_STRIDE is read/write.
  const uint32_t stride = HTX_RASTER_BASE + offsetof(HTX_RASTER_Type, FB_STRIDE);
  sim.write_reg(stride, 123);
  EXPECT_EQ(sim.read_reg(stride), 123u);
  // TEXTURE answers its registers: a descriptor is read/write.
  const uint32_t tex1 = HTX_TEXTURE_BASE + offsetof(HTX_TEXTURE_Type, TEX1);
  sim.write_reg(tex1, 0x01550042u);
  EXPECT_EQ(sim.read_reg(tex1), 0x01550042u);
  // Anything else on the register port answers with an error (no hang).
  EXPECT_THROW(sim.read_reg(0x20005000u), std::runtime_error);
  EXPECT_THROW(sim.write_reg(0x20002000u, 1), std::runtime_error);
  EXPECT_EQ(sim.read_reg(stride), 123u);  // and the port still works afterwards
}

// These models keep one colour page (double buffering is the SoC's, docs/video.md): FB_MEM says
// so, and FB_PAGE reads 0 whatever is written.
TEST_P(GpuBus, OneColourPageIgnoresTheDrawPage) {
  GpuSim sim(GetParam());
  const uint32_t mem = sim.read_reg(HTX_RASTER_BASE + offsetof(HTX_RASTER_Type, FB_MEM));
  EXPECT_EQ((mem & RASTER_FB_MEM_PAGES_Msk) >> RASTER_FB_MEM_PAGES_Pos, 1u);
  EXPECT_EQ((mem & RASTER_FB_MEM_PIXELS_Msk) >> RASTER_FB_MEM_PIXELS_Pos, 262144u);  // the models' FbPixels
  const uint32_t page = HTX_RASTER_BASE + offsetof(HTX_RASTER_Type, FB_PAGE);
  sim.write_reg(page, RASTER_FB_PAGE_DRAW_Msk);
  EXPECT_EQ(sim.read_reg(page), 0u);
}

TEST_P(GpuBus, MemoryPortReachesFramebufferDepthAndTextureWindows) {
  GpuSim sim(GetParam());
  uint32_t v = 0;
  EXPECT_FALSE(sim.mem_write(GpuSim::kColorWindow + 8, 0xBEEF1234u));
  EXPECT_FALSE(sim.mem_write(GpuSim::kDepthWindow + 12, 0x1234u));
  EXPECT_FALSE(sim.mem_write(GpuSim::kTextureWindow + 16, 0x0000A5A5u));
  EXPECT_FALSE(sim.mem_read(GpuSim::kColorWindow + 8, &v));
  EXPECT_EQ(v, 0xBEEF1234u);
  EXPECT_FALSE(sim.mem_read(GpuSim::kDepthWindow + 12, &v));
  EXPECT_EQ(v, 0x1234u);
  EXPECT_FALSE(sim.mem_read(GpuSim::kTextureWindow + 16, &v));
  EXPECT_EQ(v & 0xFFFFu, 0xA5A5u);
  // Beyond the texture memory and outside the fb windows: errors, nothing hangs.
  EXPECT_TRUE(sim.mem_write(GpuSim::kTextureWindow + 16 * sim.texture_blocks(), 1));
  EXPECT_TRUE(sim.mem_read(0x30200000u, &v));
}

TEST_P(GpuBus, TextureUploadReadsBackInTheDocumentedLayout) {
  GpuSim sim(GetParam());
  std::vector<uint8_t> px(32 * 16 * 4);
  for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<uint8_t>(i * 37 + 11);
  const Texture tex = make_texture(TexFormat::RGBA4444, 5, 4, px);
  ASSERT_EQ(GpuSim::kTextureWindow, kDocTextureWindow);
  std::vector<std::pair<uint32_t, uint32_t>> words;
  rtl::append_texture_words(tex, 7, GpuSim::kTextureWindow, words);
  size_t texels = 0;
  for (const auto& level : tex.levels) texels += level.size();
  ASSERT_EQ(words.size(), texels);
  EXPECT_EQ(rtl::texture_chain_blocks(tex), 128u + 32 + 8 + 2 + 1 + 1);
  EXPECT_EQ(sim.mem_write_burst(words), 0u);
  // Every word the uploader wrote lies in blocks 7 .. 7 + chain - 1.
  for (const auto& [addr, value] : words) {
    const uint32_t block = (addr - kDocTextureWindow) / 16;
    ASSERT_GE(block, 7u) << "address " << addr;
    ASSERT_LT(block, 7u + 128 + 32 + 8 + 2 + 1 + 1) << "address " << addr;
  }
  // Every texel of every level (32x16 down to 1x1) reads back at the document's address.
  ASSERT_EQ(tex.levels.size(), 6u);
  for (unsigned l = 0; l < tex.levels.size(); ++l) {
    const uint32_t w = std::max(1u, 32u >> l), h = std::max(1u, 16u >> l);
    ASSERT_EQ(tex.levels[l].size(), static_cast<size_t>(w) * h) << "level " << l;
    for (uint32_t j = 0; j < h; ++j)
      for (uint32_t i = 0; i < w; ++i) {
        const uint32_t addr = kDocTextureWindow + 4 * doc_word(7, 5, 4, l, i, j);
        uint32_t got = 0;
        ASSERT_FALSE(sim.mem_read(addr, &got)) << "address " << addr;
        ASSERT_EQ(got & 0xFFFFu, tex.levels[l][j * w + i]) << "level " << l << " (" << i << ", " << j << ")";
      }
  }
  // TEX descriptor: BASE[15:0], LOG2_WIDTH[19:16], LOG2_HEIGHT[23:20], FORMAT[25:24] (RGBA4444 is 1).
  EXPECT_EQ(rtl::texture_descriptor(tex, 7), 7u | (5u << 16) | (4u << 20) | (1u << 24));
}

// The board's GPU writes texture memory only (htx_tex_mem CpuRead = 0, CAPS.WINDOW_READ = 0): a read
// of the window answers an error with 0 at once and both ports go on working. (That the writes land
// is what GpuScenes checks: it draws every textured scene on this model, bit for bit.)
TEST(GpuBoardBus, TextureWindowIsWrittenOnly) {
  GpuSim sim("icebreaker_board");
  const uint32_t caps = sim.read_reg(HTX_TEXTURE_BASE + offsetof(HTX_TEXTURE_Type, CAPS));
  EXPECT_EQ(caps & TEXTURE_CAPS_WINDOW_READ_Msk, 0u);
  EXPECT_EQ((caps & TEXTURE_CAPS_SLOTS_Msk) >> TEXTURE_CAPS_SLOTS_Pos, 4u);
  EXPECT_FALSE(sim.mem_write(GpuSim::kTextureWindow + 16, 0x0000A5A5u));
  uint32_t v = 0xFFFFFFFFu;
  EXPECT_TRUE(sim.mem_read(GpuSim::kTextureWindow + 16, &v));
  EXPECT_EQ(v, 0u);
  v = 0xFFFFFFFFu;
  EXPECT_TRUE(sim.mem_read(GpuSim::kTextureWindow + 16 * sim.texture_blocks(), &v));  // beyond it, too
  EXPECT_EQ(v, 0u);
  EXPECT_TRUE(sim.mem_write(GpuSim::kTextureWindow + 16 * sim.texture_blocks(), 1));
  EXPECT_FALSE(sim.mem_write(GpuSim::kColorWindow + 8, 0xBEEF1234u));
  EXPECT_FALSE(sim.mem_read(GpuSim::kColorWindow + 8, &v));
  EXPECT_EQ(v, 0xBEEF1234u);
  const uint32_t tex1 = HTX_TEXTURE_BASE + offsetof(HTX_TEXTURE_Type, TEX1);
  sim.write_reg(tex1, 0x01550042u);
  EXPECT_EQ(sim.read_reg(tex1), 0x01550042u);
}

TEST(GpuSimConfig, UnknownConfigurationIsAnError) { EXPECT_THROW(GpuSim("tiny"), std::invalid_argument); }

INSTANTIATE_TEST_SUITE_P(Configs, GpuBus, ::testing::Values("full", "icebreaker"));

}  // namespace
}  // namespace htx
