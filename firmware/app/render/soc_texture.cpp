#include "soc_texture.hpp"

namespace render_app {

namespace {

constexpr uint32_t kWhite = 0xFFFFFFFFu;                          // 255, 255, 255, 255
constexpr uint32_t kInk = 40u | (60u << 8) | (140u << 16) | (255u << 24);  // the model's kInk

uint32_t g_scratch[htx::render::texture_upload_scratch_words(kTextureLog2, kTextureLog2)];

}  // namespace

void checker_texels(uint32_t* rgba8) {
  const uint32_t size = 1u << kTextureLog2;
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x)
      rgba8[y * size + x] = (((x >> kTextureCellLog2) ^ (y >> kTextureCellLog2)) & 1u) ? kInk : kWhite;
}

htx::render::UploadStatus upload_scene_texture(uint32_t max_polls, uint32_t* image) {
  checker_texels(image);
  htx::render::TextureImage img;
  img.rgba8 = image;
  img.log2_width = kTextureLog2;
  img.log2_height = kTextureLog2;
  img.format = 0;  // RGB565
  return htx::render::upload_texture(kTextureSlot, 0, img, g_scratch, sizeof g_scratch / sizeof g_scratch[0],
                                     max_polls);
}

}  // namespace render_app
