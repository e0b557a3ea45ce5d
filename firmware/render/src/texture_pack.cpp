#include "htx/render/texture_pack.h"

#include "htx/fw/console_packet.h"
#include "htx/fw/mip_chain.h"
#include "htx/fw/texel.h"

namespace htx::render {

namespace {

constexpr uint8_t kMagic[4] = {'H', 'T', 'X', 'T'};

const char* fields_wrong(uint32_t log2_w, uint32_t log2_h, uint32_t format) {
  if (log2_w < fw::kTexMinLog2 || log2_w > fw::kTexMaxLog2 || log2_h < fw::kTexMinLog2 || log2_h > fw::kTexMaxLog2)
    return "a side is not 8 to 256 texels";
  if (format != fw::kTexelRgb565 && format != fw::kTexelRgba4444) return "the format is not RGB565 or RGBA4444";
  return nullptr;
}

}  // namespace

size_t pack_texture(uint8_t log2_w, uint8_t log2_h, uint8_t format, const uint16_t* texels, uint8_t* out,
                    size_t capacity) {
  if (fields_wrong(log2_w, log2_h, format) || !texels) return 0;
  const size_t size = packed_texture_size(log2_w, log2_h);
  if (size > capacity) return 0;
  for (int i = 0; i < 4; ++i) out[i] = kMagic[i];
  fw::put_le16(out + 4, kTexturePackVersion);
  out[6] = log2_w;
  out[7] = log2_h;
  out[8] = format;
  out[9] = out[10] = out[11] = 0;
  const size_t count = size_t{1} << (log2_w + log2_h);
  for (size_t k = 0; k < count; ++k) fw::put_le16(out + kTexturePackHeader + 2 * k, texels[k]);
  return size;
}

const char* unpack_texture(uint8_t* bytes, size_t size, uint32_t max_texels, UnpackedTexture* out) {
  if (size < kTexturePackHeader) return "shorter than its header";
  for (int i = 0; i < 4; ++i)
    if (bytes[i] != kMagic[i]) return "not a packed texture (no HTXT)";
  if (fw::get_le16(bytes + 4) != kTexturePackVersion) return "an unknown version";
  if (const char* why = fields_wrong(bytes[6], bytes[7], bytes[8])) return why;
  if (bytes[9] || bytes[10] || bytes[11]) return "reserved bytes are not zero";
  if ((uint32_t{1} << (bytes[6] + bytes[7])) > max_texels) return "more texels than the console takes";
  if (size != packed_texture_size(bytes[6], bytes[7])) return "the size does not match its sides";
  out->log2_width = bytes[6];
  out->log2_height = bytes[7];
  out->format = bytes[8];
  out->texels = bytes + kTexturePackHeader;
  return nullptr;
}

}  // namespace htx::render
