// The console's textures (docs/console.md, "Texture upload"): one per texture slot the texture unit
// builds, up to htx::render::kConsoleTextureSlots. At boot slot 0 holds the render firmware's
// 32 x 32 checkerboard at block 0 and the others none. An uploaded texture is checked whole in RAM
// first, then written where it overlaps no texture in use, and its slot's descriptor moves to it
// only once the whole chain is there, so a refused or failed upload leaves every texture as it
// was. When texture memory has no such room but would with the slot's old texture gone, the new
// one is written over the old (the only way that can still fail is the texture unit timing out,
// which leaves the slot empty, and says so).
#pragma once

#include <stdint.h>

#include "htx/render/texture_memory.h"
#include "scene_render.hpp"

namespace console_app {

// `texture SIZE CRC32 [SLOT]`: receives a packed texture (htx/render/texture_pack.h) into `slot`,
// printing `texture ok: ...` or `error: ...`. The slot is checked before any packet is taken.
void receive_texture(uint32_t size, uint32_t crc32, uint32_t slot);

struct TextureInfo {
  uint8_t log2_width = 0, log2_height = 0, format = 0;
  bool uploaded = false;               // false: the checkerboard of boot
  htx::render::TextureRegion region;   // where its chain is, in 2 x 2-texel blocks (none: no texture)
  bool present() const { return region.blocks != 0; }
};
// The slots the console uses: the texture unit's (CAPS.SLOTS), at most kConsoleTextureSlots.
uint32_t texture_slot_count();
TextureInfo texture_in_slot(uint32_t slot);
// Texture memory's size, and the blocks the slots' chains take, in 2 x 2-texel blocks.
uint32_t texture_memory_blocks();
uint32_t texture_blocks_in_use();

// The slots' sizes as draw_scene takes them.
void fill_draw_textures(render_app::DrawSettings* draw);

// "rgb565" or "rgba4444": the formats an upload may have.
inline const char* texture_format_name(uint8_t format) { return format == 0 ? "rgb565" : "rgba4444"; }

}  // namespace console_app
