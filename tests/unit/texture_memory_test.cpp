// find_texture_gap (firmware/render texture_memory.h): the lowest run of free blocks among the
// textures in use, checked against a block-by-block search over random layouts.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "htx/render/texture_memory.h"

namespace {

using htx::render::find_texture_gap;
using htx::render::place_texture_chain;
using htx::render::TextureRegion;

// The lowest base whose `need` blocks are all free, by marking every block (total when none).
uint32_t lowest_free_run(const std::vector<TextureRegion>& live, uint32_t need, uint32_t total) {
  if (need == 0) return total;
  std::vector<bool> used(total, false);
  for (const TextureRegion& r : live)
    for (uint32_t b = r.base; b < r.base + r.blocks && b < total; ++b) used[b] = true;
  uint32_t run = 0;
  for (uint32_t b = 0; b < total; ++b) {
    run = used[b] ? 0 : run + 1;
    if (run == need) return b + 1 - need;
  }
  return total;
}

// Up to 8 live regions in `total` blocks: disjoint, some empty, in a shuffled order.
std::vector<TextureRegion> random_layout(std::mt19937& rng, uint32_t total) {
  std::vector<TextureRegion> live(1 + rng() % 8);
  uint32_t at = rng() % 32;
  for (TextureRegion& r : live) {
    if (rng() % 4 == 0) continue;
    const uint32_t blocks = 1 + rng() % (total / 4);
    if (at + blocks > total) break;
    r = {at, blocks};
    at += blocks + rng() % 64;
  }
  std::shuffle(live.begin(), live.end(), rng);
  return live;
}

TEST(TextureMemory, TheConsolesTwoTexturesAndAThird) {
  // The board's 1,024 blocks; a 32 x 32 chain takes 342.
  const uint32_t total = 1024, chain = 342;
  std::vector<TextureRegion> live(4);
  live[0] = {0, chain};  // the boot checkerboard in slot 0
  EXPECT_EQ(find_texture_gap(live.data(), 4, chain, total), chain);
  live[0] = {chain, chain};  // slot 0 replaced beside it
  EXPECT_EQ(find_texture_gap(live.data(), 4, chain, total), 0u);
  live[1] = {0, chain};
  // A third 32 x 32 does not fit (340 blocks left); one of 8 x 8 (22 blocks) does.
  EXPECT_EQ(find_texture_gap(live.data(), 4, chain, total), total);
  EXPECT_EQ(find_texture_gap(live.data(), 4, 22, total), 2 * chain);
  // Without slot 0's own texture, its replacement goes where it was.
  live[0] = {};
  EXPECT_EQ(find_texture_gap(live.data(), 4, chain, total), chain);
}

TEST(TextureMemory, EdgesOfTheMemory) {
  const TextureRegion none[1] = {};
  EXPECT_EQ(find_texture_gap(none, 1, 1024, 1024), 0u);
  EXPECT_EQ(find_texture_gap(none, 1, 1025, 1024), 1024u);
  EXPECT_EQ(find_texture_gap(none, 1, 0, 1024), 1024u) << "nothing to place";
  const TextureRegion end[1] = {{1000, 24}};
  EXPECT_EQ(find_texture_gap(end, 1, 1000, 1024), 0u);
  EXPECT_EQ(find_texture_gap(end, 1, 1001, 1024), 1024u);
  const TextureRegion start[1] = {{0, 24}};
  EXPECT_EQ(find_texture_gap(start, 1, 1000, 1024), 24u);
  EXPECT_EQ(find_texture_gap(start, 1, 1001, 1024), 1024u);
}

TEST(TextureMemory, EqualsABlockByBlockSearch) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20000; ++trial) {
    const uint32_t total = 64 + rng() % 1024;
    const std::vector<TextureRegion> live = random_layout(rng, total);
    const uint32_t need = rng() % (total / 2);
    ASSERT_EQ(find_texture_gap(live.data(), static_cast<uint32_t>(live.size()), need, total),
              lowest_free_run(live, need, total))
        << "trial " << trial;
  }
}

// The console's sequence that used to split the free space: the boot checkerboard (slot 0) at
// block 0, replaced beside itself by the uploaded cube's 32 x 32; the replacement goes to the end
// of the memory, so the 342 blocks it frees join the rest (682 free in one run) and a 64 x 16
// chain (344 blocks) still fits. Placed by the lowest gap alone it went to 342..683, leaving runs
// of 342 and 340.
TEST(TextureMemory, AReplacementBesideItsOldChainKeepsTheFreeSpaceInOneRun) {
  const uint32_t total = 1024, chain = 342, wide = 344;
  std::vector<TextureRegion> live(4);
  live[0] = {0, chain};
  const uint32_t moved = place_texture_chain(live.data(), 4, chain, total);
  EXPECT_EQ(moved, total - chain);
  live[0] = {moved, chain};
  EXPECT_EQ(place_texture_chain(live.data(), 4, wide, total), 0u);
  // Replaced again: the lowest gap (0..681) does not run to the end, so its start; the free space
  // is one run again (342..1023 after the old chain goes).
  EXPECT_EQ(place_texture_chain(live.data(), 4, chain, total), 0u);
  // A gap that is the whole memory: the chain at its end.
  const TextureRegion none[1] = {};
  EXPECT_EQ(place_texture_chain(none, 1, 22, total), total - 22);
  EXPECT_EQ(place_texture_chain(none, 1, total + 1, total), total);
  EXPECT_EQ(place_texture_chain(none, 1, 0, total), total);
}

// Wherever it places a chain, every block of it is free and inside the memory, in the gap the
// lowest-gap search found: at its start, or at the memory's end when that gap runs to it.
TEST(TextureMemory, PlacementIsAFreeRunInTheLowestGap) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20000; ++trial) {
    const uint32_t total = 64 + rng() % 1024;
    const std::vector<TextureRegion> live = random_layout(rng, total);
    const uint32_t need = 1 + rng() % (total / 2);
    const uint32_t count = static_cast<uint32_t>(live.size());
    const uint32_t lowest = lowest_free_run(live, need, total);
    const uint32_t placed = place_texture_chain(live.data(), count, need, total);
    if (lowest == total) {
      ASSERT_EQ(placed, total) << "trial " << trial;
      continue;
    }
    bool runs_to_end = true;
    for (const TextureRegion& r : live)
      if (r.blocks != 0 && r.base + r.blocks > lowest) runs_to_end = false;
    ASSERT_EQ(placed, runs_to_end ? total - need : lowest) << "trial " << trial;
  }
}

}  // namespace
