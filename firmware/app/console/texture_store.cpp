#include "texture_store.hpp"

#include <stdio.h>

#include "htx/fw/mip_chain.h"
#include "htx/hal/texture.h"
#include "htx/render/texture_pack.h"
#include "htx/render/texture_upload.h"
#include "packet_receive.hpp"
#include "scene_store.hpp"
#include "soc_texture.hpp"

namespace console_app {

namespace {

static_assert(htx::render::kConsoleTextureBytes <= kStoreBytes, "the staging buffer holds the largest texture");

constexpr uint32_t kMaxPolls = 20'000'000;

TextureInfo g_texture{render_app::kTextureLog2, render_app::kTextureLog2, 0, false};
uint32_t g_half = 0;  // the half of texture memory the texture is in (the boot texture: 0)

}  // namespace

TextureInfo current_texture() { return g_texture; }

void receive_texture(uint32_t size, uint32_t crc32) {
  if (!receive_packets(size, crc32, htx::render::kConsoleTextureBytes, "texture")) return;
  htx::render::UnpackedTexture t;
  const char* why = htx::render::unpack_texture(staging_bytes(), size, htx::render::kConsoleTextureTexels, &t);
  const htx::hal::TextureCaps caps = htx::hal::texture_caps();
  const uint32_t half_blocks = (1u << caps.block_bits) / 2;
  if (!why && !((caps.formats >> t.format) & 1u)) why = "this GPU does not build its format (CAPS.FORMATS)";
  if (!why && htx::hal::texture_chain_blocks(t.log2_width, t.log2_height) > half_blocks)
    why = "its mip chain does not fit half of the texture memory";
  if (why) {
    printf("error: not a valid texture (%s); the texture is unchanged\r\n", why);
    return;
  }
  const uint32_t half = g_half ^ 1u;
  htx::hal::TextureStatus hal_status = htx::hal::kTextureOk;
  const htx::render::UploadStatus st =
      htx::render::upload_texture_texels16(render_app::kTextureSlot, half * half_blocks, t.log2_width, t.log2_height,
                                           t.format, t.texels, kMaxPolls, &hal_status);
  if (st != htx::render::kUploadOk) {
    printf("error: the texture unit refused it (upload status %d, driver status %d); the texture is unchanged\r\n",
           static_cast<int>(st), static_cast<int>(hal_status));
    return;
  }
  g_half = half;
  g_texture = {t.log2_width, t.log2_height, t.format, true};
  printf("texture ok: %ux%u %s, %lu levels; every `render` draws with it\r\n", 1u << t.log2_width,
         1u << t.log2_height, texture_format_name(t.format),
         static_cast<unsigned long>(htx::fw::mip_level_count(t.log2_width, t.log2_height)));
}

}  // namespace console_app
