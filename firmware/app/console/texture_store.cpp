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
static_assert(render_app::kTextureSlot == 0, "the boot texture is slot 0's");

constexpr uint32_t kSlots = htx::render::kConsoleTextureSlots;
constexpr uint32_t kMaxPolls = 20'000'000;

// Slot 0 at boot: the checkerboard the render firmware uploaded at block 0.
TextureInfo g_slots[kSlots] = {
    {render_app::kTextureLog2, render_app::kTextureLog2, 0, false,
     {0, htx::hal::texture_chain_blocks(render_app::kTextureLog2, render_app::kTextureLog2)}}};

htx::render::TextureRegion g_live[kSlots];

// The regions in use, without `except`'s (kSlots: every slot's).
const htx::render::TextureRegion* live_regions(uint32_t except) {
  for (uint32_t s = 0; s < kSlots; ++s) g_live[s] = s == except ? htx::render::TextureRegion{} : g_slots[s].region;
  return g_live;
}

}  // namespace

uint32_t texture_blocks_in_use() {
  uint32_t n = 0;
  for (const TextureInfo& t : g_slots) n += t.region.blocks;
  return n;
}

uint32_t texture_slot_count() {
  const uint32_t built = htx::hal::texture_caps().slots;
  return built < kSlots ? built : kSlots;
}

TextureInfo texture_in_slot(uint32_t slot) { return slot < kSlots ? g_slots[slot] : TextureInfo{}; }

uint32_t texture_memory_blocks() { return 1u << htx::hal::texture_caps().block_bits; }

void fill_draw_textures(render_app::DrawSettings* draw) {
  const uint32_t n = texture_slot_count();
  for (uint32_t s = 0; s < render_app::kDrawTextureSlots; ++s) {
    const TextureInfo t = s < n ? g_slots[s] : TextureInfo{};
    draw->textures[s] = {t.log2_width, t.log2_height, t.present()};
  }
}

void receive_texture(uint32_t size, uint32_t crc32, uint32_t slot) {
  const uint32_t slots = texture_slot_count();
  if (slot >= slots) {
    printf("error: texture slot %lu is not one of the console's 0..%lu; nothing was received\r\n",
           static_cast<unsigned long>(slot), static_cast<unsigned long>(slots - 1));
    return;
  }
  if (!receive_packets(size, crc32, htx::render::kConsoleTextureBytes, "texture")) return;
  htx::render::UnpackedTexture t;
  const char* why = htx::render::unpack_texture(staging_bytes(), size, htx::render::kConsoleTextureTexels, &t);
  if (!why && !((htx::hal::texture_caps().formats >> t.format) & 1u))
    why = "this GPU does not build its format (CAPS.FORMATS)";
  const uint32_t total = texture_memory_blocks();
  const uint32_t need = why ? 0 : htx::hal::texture_chain_blocks(t.log2_width, t.log2_height);
  // Beside every texture in use if it fits, so that a failure changes nothing; else over this
  // slot's own.
  uint32_t base = why ? total : htx::render::place_texture_chain(live_regions(kSlots), kSlots, need, total);
  const bool over_own = !why && base == total;
  if (over_own) base = htx::render::place_texture_chain(live_regions(slot), kSlots, need, total);
  if (!why && base == total) why = "its mip chain does not fit beside the other slots' textures";
  if (why) {
    printf("error: not a valid texture (%s); the texture is unchanged\r\n", why);
    return;
  }
  TextureInfo& s = g_slots[slot];
  if (over_own) s = TextureInfo{};
  htx::hal::TextureStatus hal_status = htx::hal::kTextureOk;
  const htx::render::UploadStatus st = htx::render::upload_texture_texels16(
      slot, base, t.log2_width, t.log2_height, t.format, t.texels, kMaxPolls, &hal_status);
  if (st != htx::render::kUploadOk) {
    printf("error: the texture unit refused it (upload status %d, driver status %d); %s\r\n", static_cast<int>(st),
           static_cast<int>(hal_status),
           over_own ? "the slot's texture was being overwritten and the slot is now empty" : "the texture is unchanged");
    return;
  }
  s = {t.log2_width, t.log2_height, t.format, true, {base, need}};
  printf("texture ok: %ux%u %s, %lu levels, slot %lu at blocks %lu..%lu (%lu of %lu in use)\r\n",
         1u << t.log2_width, 1u << t.log2_height, texture_format_name(t.format),
         static_cast<unsigned long>(htx::fw::mip_level_count(t.log2_width, t.log2_height)),
         static_cast<unsigned long>(slot), static_cast<unsigned long>(base), static_cast<unsigned long>(base + need - 1),
         static_cast<unsigned long>(texture_blocks_in_use()), static_cast<unsigned long>(total));
}

}  // namespace console_app
