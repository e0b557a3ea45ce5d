#include "htx/render/texture_upload.h"

#include "htx/fw/mip_chain.h"
#include "htx/fw/texel.h"

namespace htx::render {

UploadStatus upload_texture(uint32_t slot, uint32_t base_block, const TextureImage& img, uint32_t* scratch,
                            uint32_t scratch_words, uint32_t max_polls, hal::TextureStatus* hal_status) {
  const uint32_t lw = img.log2_width, lh = img.log2_height;
  const hal::TextureStatus st = hal::texture_check(slot, base_block, lw, lh, img.format);
  if (hal_status) *hal_status = st;
  if (st != hal::kTextureOk || !img.rgba8) return kUploadBadTexture;
  if (scratch_words < texture_upload_scratch_words(lw, lh) || !scratch) return kUploadScratchTooSmall;

  // Level 0: each pixel encoded straight into the window.
  const uint32_t w = 1u << lw, h = 1u << lh;
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i)
      hal::texture_write_texel(base_block, lw, lh, 0, i, j, fw::encode_texel(img.format, img.rgba8[j * w + i]));
  // Level 1 from the image, every further level in place in the scratch buffer.
  const unsigned levels = fw::mip_level_count(lw, lh);
  for (unsigned level = 1; level < levels; ++level) {
    const unsigned above_w = fw::mip_level_log2(lw, level - 1), above_h = fw::mip_level_log2(lh, level - 1);
    if (level == 1) fw::mip_next_level(img.format, img.rgba8, fw::kMipSourceRgba8, above_w, above_h, scratch);
    else fw::mip_next_level(img.format, scratch, fw::kMipSourceTexels, above_w, above_h, scratch);
    hal::texture_write_level(base_block, lw, lh, level, scratch);
  }
  const hal::TextureStatus ds = hal::texture_set_descriptor(slot, base_block, lw, lh, img.format, max_polls);
  if (hal_status) *hal_status = ds;
  return ds == hal::kTextureOk ? kUploadOk : kUploadTimeout;
}

}  // namespace htx::render
