// The packed scene of a console upload (firmware/render scene_pack.h): the model's scenes survive
// pack and unpack field for field, and unpack_scene refuses every malformed or out-of-range input
// with a message, at every truncation, without reading past the bytes it is given.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <utility>
#include <string>
#include <vector>

#include "htx/host/render_scene.hpp"
#include "htx/model/scenes.hpp"
#include "htx/render/scene_pack.h"

namespace {

using htx::render::Mesh;

struct Packed {
  htx::host::RenderScene scene;
  std::vector<uint8_t> bytes;
};

Packed pack(const std::string& name) {
  Packed p{htx::host::to_render_scene(htx::load_scene(name), 160, 120), {}};
  std::vector<Mesh> meshes;
  for (const auto& d : p.scene.meshes) meshes.push_back(d.mesh);
  p.bytes.resize(htx::render::packed_scene_size(meshes.data(), static_cast<uint32_t>(meshes.size())));
  EXPECT_EQ(htx::render::pack_scene(p.scene.view_proj, p.scene.cull_backfaces, meshes.data(),
                                    static_cast<uint32_t>(meshes.size()), p.bytes.data(), p.bytes.size()),
            p.bytes.size());
  return p;
}

// Unpacks from a word-aligned copy, as the console's store holds it.
const char* unpack(const std::vector<uint8_t>& bytes, std::vector<Mesh>* meshes, htx::render::UnpackedScene* out,
                   uint32_t max_meshes = 8, uint32_t max_vertices = 96) {
  static std::vector<uint32_t> words;
  words.assign((bytes.size() + 3) / 4 + 1, 0);
  if (!bytes.empty()) std::memcpy(words.data(), bytes.data(), bytes.size());
  meshes->assign(max_meshes, Mesh{});
  return htx::render::unpack_scene(reinterpret_cast<const uint8_t*>(words.data()), bytes.size(), meshes->data(),
                                   max_meshes, max_vertices, out);
}

TEST(ScenePack, ModelScenesRoundTripFieldForField) {
  for (const char* name : {"cube", "floor"}) {
    const Packed p = pack(name);
    std::vector<Mesh> meshes;
    htx::render::UnpackedScene u;
    ASSERT_EQ(unpack(p.bytes, &meshes, &u), nullptr) << name;
    ASSERT_EQ(u.mesh_count, p.scene.meshes.size());
    EXPECT_EQ(u.cull_backfaces, p.scene.cull_backfaces);
    EXPECT_EQ(0, std::memcmp(&u.view_proj, &p.scene.view_proj, sizeof u.view_proj));
    for (size_t m = 0; m < u.mesh_count; ++m) {
      const Mesh& a = meshes[m];
      const Mesh& b = p.scene.meshes[m].mesh;
      ASSERT_EQ(a.vertex_count, b.vertex_count);
      ASSERT_EQ(a.triangle_count, b.triangle_count);
      EXPECT_EQ(0, std::memcmp(a.vertices, b.vertices, sizeof(htx::render::MeshVertex) * a.vertex_count));
      EXPECT_EQ(0, std::memcmp(a.indices, b.indices, 6 * a.triangle_count));
      EXPECT_EQ(0, std::memcmp(&a.model, &b.model, sizeof a.model));
      EXPECT_EQ(0, std::memcmp(&a.state, &b.state, sizeof a.state));
      EXPECT_EQ(a.tex.log2_width, b.tex.log2_width);
      EXPECT_EQ(a.position_bits, b.position_bits);
    }
  }
  EXPECT_EQ(pack("cube").bytes.size(), 816u);
  EXPECT_EQ(pack("floor").bytes.size(), 2880u);
}

TEST(ScenePack, EveryTruncationAndExtensionIsRefused) {
  const Packed p = pack("cube");
  std::vector<Mesh> meshes;
  htx::render::UnpackedScene u;
  for (size_t n = 0; n < p.bytes.size(); ++n) {
    const std::vector<uint8_t> cut(p.bytes.begin(), p.bytes.begin() + static_cast<long>(n));
    EXPECT_NE(unpack(cut, &meshes, &u), nullptr) << n;
  }
  std::vector<uint8_t> longer = p.bytes;
  longer.insert(longer.end(), {0, 0, 0, 0});
  EXPECT_STREQ(unpack(longer, &meshes, &u), "bytes left over after the last mesh");
}

TEST(ScenePack, OutOfRangeFieldsAreRefusedWithTheirReason) {
  const Packed p = pack("cube");
  const size_t mesh = htx::render::kScenePackHeader, state = mesh + 72, verts = mesh + htx::render::kScenePackMeshHeader;
  const size_t indices = verts + 24 * 24;
  struct Case {
    size_t at;
    uint8_t value;
    const char* why;
  };
  const Case cases[] = {
      {0, 'X', "not a packed scene (no HTXS)"},
      {4, 2, "unknown version"},
      {6, 0, "no meshes"},
      {6, 9, "more meshes than the console holds"},
      {8, 2, "bad cull flag"},
      {12 + 64, 40, "camera matrix fraction out of range"},
      {mesh, 0, "empty mesh"},
      {mesh, 97, "a mesh has more vertices than the console's vertex cache"},
      {mesh + 4 + 64, 3, "model matrix fraction out of range"},
      {state, 5, "state field out of range"},       // method 5 (QUADRATIC) is not built
      {state + 1, 1, "state field out of range"},   // SUBDIV 1
      {state + 2, 3, "state field out of range"},   // filter
      {state + 5, 6, "state field out of range"},   // depth function
      {state + 6, 2, "bad state flag"},
      {state + 11, 9, "texture size out of range"},
      {verts + 3, 0x40, "a position is 2^14 or more"},  // x = 2^30: 2^14 in Q16.16
      {indices, 24, "an index is past its mesh's vertices"},
  };
  for (const Case& c : cases) {
    std::vector<uint8_t> bad = p.bytes;
    bad[c.at] = c.value;
    std::vector<Mesh> meshes;
    htx::render::UnpackedScene u;
    const char* why = unpack(bad, &meshes, &u, 8, 96);
    ASSERT_NE(why, nullptr) << c.why;
    EXPECT_STREQ(why, c.why) << "byte " << c.at;
  }
  // The limits are the caller's: the cube (24 vertices) does not fit a cache of 16.
  std::vector<Mesh> meshes;
  htx::render::UnpackedScene u;
  EXPECT_STREQ(unpack(p.bytes, &meshes, &u, 8, 16), "a mesh has more vertices than the console's vertex cache");
  uint8_t small[100];
  EXPECT_EQ(htx::render::pack_scene(p.scene.view_proj, true, &p.scene.meshes[0].mesh, 1, small, sizeof small), 0u);
}

// The triangles of a scene as vertex values, mesh after mesh, with each mesh's model and state.
struct DrawnTriangle {
  htx::render::MeshVertex v[3];
  int32_t model00;
  uint8_t method;
  int8_t position_bits;
};
std::vector<DrawnTriangle> drawn(const htx::host::RenderScene& rs) {
  std::vector<DrawnTriangle> out;
  for (const auto& d : rs.meshes)
    for (uint32_t t = 0; t < d.mesh.triangle_count; ++t) {
      DrawnTriangle tri{};
      for (int k = 0; k < 3; ++k) tri.v[k] = d.mesh.vertices[d.mesh.indices[3 * t + k]];
      tri.model00 = d.mesh.model.m[0][0];
      tri.method = d.mesh.state.method;
      tri.position_bits = d.mesh.position_bits;
      out.push_back(tri);
    }
  return out;
}
bool same(const htx::render::MeshVertex& a, const htx::render::MeshVertex& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.s == b.s && a.t == b.t && a.rgba == b.rgba;
}

// Split meshes draw the whole meshes' triangles in the same order, with the same matrix, state and
// transform precision (position bits), in parts of at most the limit; they pack and unpack.
TEST(SplitMeshes, PartsDrawTheWholeMeshesTrianglesWithTheirPrecision) {
  for (const auto& [name, limit] : {std::pair<const char*, uint32_t>{"floor", 30}, {"floor", 4}, {"tunnel", 96},
                                    {"randmesh", 20}, {"cube", 96}}) {
    htx::host::RenderScene rs = htx::host::to_render_scene(htx::load_scene(name), 160, 120);
    const std::vector<DrawnTriangle> before = drawn(rs);
    const size_t meshes_before = rs.meshes.size();
    uint32_t largest = 0;
    for (const auto& d : rs.meshes) largest = std::max(largest, d.mesh.vertex_count);
    htx::host::split_meshes(&rs, limit);
    if (largest <= limit) EXPECT_EQ(rs.meshes.size(), meshes_before) << name;
    else EXPECT_GT(rs.meshes.size(), meshes_before) << name << " " << limit;
    for (const auto& d : rs.meshes) {
      ASSERT_LE(d.mesh.vertex_count, limit) << name;
      ASSERT_EQ(d.mesh.vertices, d.vertices.data());
      ASSERT_EQ(d.mesh.position_bits,
                htx::render::mesh_position_bits(d.vertices.data(), static_cast<uint32_t>(d.vertices.size())));
    }
    const std::vector<DrawnTriangle> after = drawn(rs);
    ASSERT_EQ(after.size(), before.size()) << name;
    for (size_t t = 0; t < before.size(); ++t) {
      for (int k = 0; k < 3; ++k) ASSERT_TRUE(same(after[t].v[k], before[t].v[k])) << name << " triangle " << t;
      ASSERT_EQ(after[t].model00, before[t].model00);
      ASSERT_EQ(after[t].method, before[t].method);
      ASSERT_EQ(after[t].position_bits, before[t].position_bits) << name << " triangle " << t << " limit " << limit;
    }
    // They pack, and the console takes them back (at most kStoreMeshes = 32 parts of 96 vertices).
    std::vector<Mesh> meshes;
    for (const auto& d : rs.meshes) meshes.push_back(d.mesh);
    std::vector<uint8_t> bytes(htx::render::packed_scene_size(meshes.data(), static_cast<uint32_t>(meshes.size())));
    ASSERT_EQ(htx::render::pack_scene(rs.view_proj, rs.cull_backfaces, meshes.data(),
                                      static_cast<uint32_t>(meshes.size()), bytes.data(), bytes.size()),
              bytes.size());
    std::vector<Mesh> unpacked;
    htx::render::UnpackedScene u;
    const uint32_t parts = static_cast<uint32_t>(rs.meshes.size());
    ASSERT_EQ(unpack(bytes, &unpacked, &u, parts, limit), nullptr) << name;
    EXPECT_EQ(u.triangle_count, before.size());
  }
  htx::host::RenderScene rs = htx::host::to_render_scene(htx::load_scene("floor"), 160, 120);
  EXPECT_THROW(htx::host::split_meshes(&rs, 3), std::invalid_argument);
}

}  // namespace
