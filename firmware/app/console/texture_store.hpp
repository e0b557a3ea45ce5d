// The console's texture (docs/console.md, "Texture upload"): slot 0, which every `render` draws
// with. At boot the render firmware's 32 x 32 checkerboard in the first half of texture memory; an
// uploaded texture is written into the half not in use, and the descriptor moves to it only once
// the whole chain is there, so a refused or failed upload leaves the texture as it was.
#pragma once

#include <stdint.h>

namespace console_app {

// `texture SIZE CRC32`: receives a packed texture (htx/render/texture_pack.h) and makes it the
// texture, printing `texture ok: ...` or `error: ...; the texture is unchanged`.
void receive_texture(uint32_t size, uint32_t crc32);

struct TextureInfo {
  uint8_t log2_width, log2_height, format;
  bool uploaded;  // false: the checkerboard of boot
};
TextureInfo current_texture();

// "rgb565" or "rgba4444": the formats an upload may have.
inline const char* texture_format_name(uint8_t format) { return format == 0 ? "rgb565" : "rgba4444"; }

}  // namespace console_app
