// The packed scene a host uploads to the console (docs/console.md, "Scene upload"): the firmware
// render pipeline's meshes and camera in one little-endian byte string, written by the host
// (pack_scene) and checked and read in place by the firmware (unpack_scene), so both use one
// definition of the format. Freestanding C++17.
//
//   header   "HTXS", u16 version (1), u16 mesh count, u8 cull back faces, 3 bytes zero,
//            view_proj (16 x i32 row-major, i32 frac)                                  80 bytes
//   per mesh u16 vertex count, u16 triangle count, model (16 x i32, i32 frac),
//            state (method, subdiv_n, filter, wrap_u, wrap_v, depth_func, depth_write, textured,
//            gouraud, combine, texture: 11 bytes), texture log2 width and height, 3 bytes zero
//                                                                                      88 bytes
//            vertices (x, y, z, s, t as i32 Q16.16, rgba u32: 24 bytes each)
//            indices (u16, three per triangle), zero-padded to a multiple of 4
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "htx/render/pipeline.h"

namespace htx::render {

inline constexpr uint16_t kScenePackVersion = 1;
// The most vertices of a mesh the firmware takes: its applications' vertex caches hold a mesh whole
// (render_app::kMaxMeshVertices); the console refuses larger meshes and htx upload splits them.
inline constexpr uint32_t kMaxPackedMeshVertices = 96;
// What one upload to the console holds (its scene store, firmware/app/console/scene_store.hpp):
// htx sends a larger scene in parts, each drawn over the last (docs/console.md, "Scene upload").
inline constexpr uint32_t kConsoleSceneBytes = 16384;
inline constexpr uint32_t kConsoleSceneMeshes = 32;
inline constexpr size_t kScenePackHeader = 80;
inline constexpr size_t kScenePackMeshHeader = 88;

// The bytes pack_scene writes for these meshes.
size_t packed_scene_size(const Mesh* meshes, uint32_t mesh_count);

// Writes the packed scene into out (at least packed_scene_size bytes); returns the size, or 0 when
// `capacity` is too small or a count does not fit its field.
size_t pack_scene(const Mat4& view_proj, bool cull_backfaces, const Mesh* meshes, uint32_t mesh_count, uint8_t* out,
                  size_t capacity);

// A packed scene read in place: the meshes' vertex and index pointers point into the packed bytes,
// which must stay where they are (4-byte aligned) while the meshes are drawn.
struct UnpackedScene {
  Mat4 view_proj;
  bool cull_backfaces = true;
  uint32_t mesh_count = 0;
  uint32_t triangle_count = 0;
};

// Checks everything the pipeline relies on and fills meshes[0 .. mesh_count): returns nullptr, or
// a message saying what is wrong (the bytes are then not used). Limits: at most max_meshes meshes
// and max_vertices vertices per mesh; every index below its mesh's vertex count; positions below
// 2^14 in magnitude; matrix fractions in kMatMinFrac..kMatMaxFrac; state fields in range (methods
// 0..4 or AUTO, SUBDIV 2..64); the sizes adding up to exactly `size` bytes.
const char* unpack_scene(const uint8_t* bytes, size_t size, Mesh* meshes, uint32_t max_meshes, uint32_t max_vertices,
                         UnpackedScene* out);

}  // namespace htx::render
