#include "htx/render/texture_memory.h"

namespace htx::render {

namespace {

bool overlaps(const TextureRegion& r, uint32_t base, uint32_t blocks) {
  return r.blocks != 0 && r.base < base + blocks && base < r.base + r.blocks;
}

bool free_run(const TextureRegion* live, uint32_t count, uint32_t base, uint32_t need, uint32_t total) {
  if (base > total || total - base < need) return false;
  for (uint32_t i = 0; i < count; ++i)
    if (overlaps(live[i], base, need)) return false;
  return true;
}

}  // namespace

uint32_t find_texture_gap(const TextureRegion* live, uint32_t count, uint32_t need, uint32_t total) {
  if (need == 0) return total;
  // The lowest free run starts at 0 or where a live region ends: try those (a handful of slots).
  uint32_t best = total;
  if (free_run(live, count, 0, need, total)) return 0;
  for (uint32_t i = 0; i < count; ++i) {
    if (live[i].blocks == 0) continue;
    const uint32_t base = live[i].base + live[i].blocks;
    if (base < best && free_run(live, count, base, need, total)) best = base;
  }
  return best;
}

uint32_t place_texture_chain(const TextureRegion* live, uint32_t count, uint32_t need, uint32_t total) {
  const uint32_t base = find_texture_gap(live, count, need, total);
  if (base == total) return total;
  return free_run(live, count, base, total - base, total) ? total - need : base;
}

}  // namespace htx::render
