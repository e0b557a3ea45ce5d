// The texture the render firmware draws the built-in scenes with: the model's default checkerboard
// (white and ink, hw/model/src/scene/builtin) at half its size, 32 x 32 texels in 4-texel cells, so
// the squares are the same on screen and its whole mip chain (1,365 texels) fits the board's 4K-texel
// texture memory (the model's 64 x 64 chain needs 5,461). Generated and uploaded by the firmware
// (the chain through firmware/render's upload_texture); the system test uploads it the same way on
// its cosim reference.
#pragma once

#include <stdint.h>

#include "htx/render/texture_upload.h"

namespace render_app {

inline constexpr uint8_t kTextureLog2 = 5;      // 32 x 32 texels
inline constexpr uint8_t kTextureCellLog2 = 2;  // 4 x 4-texel squares
inline constexpr uint32_t kTextureSlot = 0;
inline constexpr uint32_t kTextureTexels = 1u << (2 * kTextureLog2);

// The level-0 image, RGBA8 (r in bits 7:0), row-major.
void checker_texels(uint32_t* rgba8);

// Generates the image in `image` (kTextureTexels words of scratch, free again afterwards: the
// console lends its scene store), uploads it with its mip chain at block 0 into kTextureSlot
// (RGB565) and returns upload_texture's status.
htx::render::UploadStatus upload_scene_texture(uint32_t max_polls, uint32_t* image);

}  // namespace render_app
