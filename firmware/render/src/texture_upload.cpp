#include "htx/render/texture_upload.h"

#include "htx/fw/console_packet.h"
#include "htx/fw/mip_chain.h"
#include "htx/fw/texel.h"
#include "htx/hal/raster.h"

namespace htx::render {

namespace {

// No texel or descriptor changes under a textured triangle in flight: the texture unit's own BUSY
// can fall between two fragments of one triangle, the raster unit's covers them all.
bool raster_idle_for_texels(uint32_t max_polls) { return hal::raster_wait_idle(max_polls); }

// Levels 2 and below generated in place from level 1 in `level` and written, each level with
// level 1 first; then the descriptor.
UploadStatus finish_chain(uint32_t slot, uint32_t base_block, uint32_t lw, uint32_t lh, uint8_t format,
                          uint32_t* level, uint32_t max_polls, hal::TextureStatus* hal_status) {
  const unsigned levels = fw::mip_level_count(lw, lh);
  for (unsigned l = 1; l < levels; ++l) {
    if (l > 1)
      fw::mip_next_level(format, level, fw::kMipSourceTexels, fw::mip_level_log2(lw, l - 1),
                         fw::mip_level_log2(lh, l - 1), level);
    hal::texture_write_level(base_block, lw, lh, l, level);
  }
  const hal::TextureStatus ds = hal::texture_set_descriptor(slot, base_block, lw, lh, format, max_polls);
  if (hal_status) *hal_status = ds;
  return ds == hal::kTextureOk ? kUploadOk : kUploadTimeout;
}

}  // namespace

UploadStatus upload_texture(uint32_t slot, uint32_t base_block, const TextureImage& img, uint32_t* scratch,
                            uint32_t scratch_words, uint32_t max_polls, hal::TextureStatus* hal_status) {
  const uint32_t lw = img.log2_width, lh = img.log2_height;
  const hal::TextureStatus st = hal::texture_check(slot, base_block, lw, lh, img.format);
  if (hal_status) *hal_status = st;
  if (st != hal::kTextureOk || !img.rgba8) return kUploadBadTexture;
  if (scratch_words < texture_upload_scratch_words(lw, lh) || !scratch) return kUploadScratchTooSmall;
  if (!raster_idle_for_texels(max_polls)) return kUploadTimeout;

  // Level 0: each pixel encoded straight into the window.
  const uint32_t w = 1u << lw, h = 1u << lh;
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i)
      hal::texture_write_texel(base_block, lw, lh, 0, i, j, fw::encode_texel(img.format, img.rgba8[j * w + i]));
  // Level 1 from the image into the scratch buffer, every further level in place there.
  fw::mip_next_level(img.format, img.rgba8, fw::kMipSourceRgba8, lw, lh, scratch);
  return finish_chain(slot, base_block, lw, lh, img.format, scratch, max_polls, hal_status);
}

UploadStatus upload_texture_texels16(uint32_t slot, uint32_t base_block, uint8_t log2_w, uint8_t log2_h,
                                     uint8_t format, uint8_t* texels, uint32_t max_polls,
                                     hal::TextureStatus* hal_status) {
  const hal::TextureStatus st = hal::texture_check(slot, base_block, log2_w, log2_h, format);
  if (hal_status) *hal_status = st;
  const bool sixteen_bits = format == fw::kTexelRgb565 || format == fw::kTexelRgba4444;
  if (st != hal::kTextureOk || !sixteen_bits || !texels) return kUploadBadTexture;
  if (!raster_idle_for_texels(max_polls)) return kUploadTimeout;

  const uint32_t w = 1u << log2_w, h = 1u << log2_h;
  const auto texel = [texels, w](uint32_t i, uint32_t j) { return fw::get_le16(texels + 2u * (j * w + i)); };
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) hal::texture_write_texel(base_block, log2_w, log2_h, 0, i, j, texel(i, j));
  // Level 1, one 2x2 box at a time (both sides are at least 8, so every box is a full 2x2), each
  // read completely before its word is written over the level-0 texels it read last.
  uint32_t* level = reinterpret_cast<uint32_t*>(texels);
  for (uint32_t j = 0; j < h / 2; ++j)
    for (uint32_t i = 0; i < w / 2; ++i) {
      const uint32_t box[4] = {texel(2 * i, 2 * j), texel(2 * i + 1, 2 * j), texel(2 * i, 2 * j + 1),
                               texel(2 * i + 1, 2 * j + 1)};
      uint32_t out = 0;
      fw::mip_next_level(format, box, fw::kMipSourceTexels, 1, 1, &out);
      level[j * (w / 2) + i] = out;
    }
  return finish_chain(slot, base_block, log2_w, log2_h, format, level, max_polls, hal_status);
}

}  // namespace htx::render
