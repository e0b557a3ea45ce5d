// The console's scene unpacker (firmware/render scene_pack.cpp), compiled here with the address and
// undefined-behaviour sanitizers, fed a valid packed scene with random damage: it never reads past
// its bytes, and whatever it accepts keeps every promise the render pipeline relies on.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "htx/host/render_scene.hpp"
#include "htx/model/scenes.hpp"
#include "htx/render/scene_pack.h"

namespace {

TEST(ScenePackFuzz, DamagedScenesAreRefusedOrSafe) {
  const htx::host::RenderScene rs = htx::host::to_render_scene(htx::load_scene("cube"), 160, 120);
  std::vector<uint8_t> good(htx::render::packed_scene_size(&rs.meshes[0].mesh, 1));
  ASSERT_EQ(htx::render::pack_scene(rs.view_proj, true, &rs.meshes[0].mesh, 1, good.data(), good.size()), good.size());
  std::mt19937 rng(1203);
  size_t accepted = 0;
  for (int round = 0; round < 20000; ++round) {
    std::vector<uint8_t> bytes = good;
    const int damage = static_cast<int>(rng() % 4);
    for (int k = 0; k <= damage; ++k) bytes[rng() % bytes.size()] = static_cast<uint8_t>(rng());
    if (rng() % 4 == 0) bytes.resize(rng() % (bytes.size() + 16));
    // Exactly the bytes given, in a heap block of their own size (ASan sees a read even one byte
    // past them; operator new's 16-byte alignment keeps the unpacker's word reads aligned).
    const std::unique_ptr<uint8_t[]> exact(new uint8_t[bytes.size()]);
    if (!bytes.empty()) std::memcpy(exact.get(), bytes.data(), bytes.size());
    htx::render::Mesh meshes[2];
    htx::render::UnpackedScene u;
    const char* why = htx::render::unpack_scene(exact.get(), bytes.size(), meshes, 2, 96, &u);
    if (why) continue;
    ++accepted;
    ASSERT_GE(u.mesh_count, 1u);
    for (uint32_t m = 0; m < u.mesh_count; ++m) {
      ASSERT_LE(meshes[m].vertex_count, 96u);
      for (uint32_t i = 0; i < 3 * meshes[m].triangle_count; ++i) ASSERT_LT(meshes[m].indices[i], meshes[m].vertex_count);
      ASSERT_LE(meshes[m].position_bits, 14);
    }
  }
  // Damage to vertex values, colours and matrices is legal data: some rounds are accepted.
  EXPECT_GT(accepted, 100u);
}

}  // namespace
