// A host Scene (hw/model) as the firmware render pipeline takes it: Q16.16 meshes and fixed-point
// matrices. Used by `htx upload` (packed with htx/render/scene_pack.h), by the firmware's
// compiled-in scene data generator and by the tests that compare the firmware with the model.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/model/scene.hpp"
#include "htx/render/pipeline.h"

namespace htx::host {

int32_t to_q16(double x);  // round(x * 2^16), checked against the Q16.16 range (throws)
// Linear part with the most fraction bits (16..30) its largest entry allows, translation Q16.16.
render::Mat4 to_mat4_fx(const Mat4& m);

// The firmware form of a scene's meshes; owns the arrays the render::Mesh views point at.
struct RenderScene {
  struct MeshData {
    std::vector<render::MeshVertex> vertices;
    std::vector<uint16_t> indices;
    // A whole mesh of more than 65536 vertices (to_render_scene with keep_wide): its indices, until
    // split_meshes cuts it into parts with 16-bit ones; `indices` is empty and mesh.indices null.
    std::vector<uint32_t> wide_indices;
    render::Mesh mesh{};
    uint32_t source = 0;  // the index of the Scene mesh it comes from (split_meshes keeps it)
  };
  std::vector<MeshData> meshes;
  render::Mat4 view_proj{};
  int width = 0, height = 0;
  bool cull_backfaces = true;
};

// Converts with the host's camera (projection * view for the screen's aspect). Throws
// std::out_of_range when a value leaves Q16.16 or (naming the mesh), unless keep_wide, a mesh has
// more than 65536 vertices (keep_wide: such a mesh keeps wide_indices, for split_meshes).
// render::TriState's texture is a byte: a scene of more than 256 textures names its meshes'
// textures by the Scene meshes' own (MeshData::source), as scene_payload does.
RenderScene to_render_scene(const Scene& scene, int width, int height, bool keep_wide = false);

render::TriState to_render_state(const TriState& s);

// Splits every mesh of more than max_vertices vertices (at least 4) into meshes of at most that
// many (the console's vertex cache), with the same matrix and state and the triangles in the same
// order, so they draw what the whole mesh draws. Each part keeps the whole mesh's transform
// precision: a part whose own coordinates need fewer integer bits (mesh_position_bits) also
// carries the mesh's largest vertex, unreferenced, so that every copy of a shared vertex is
// transformed alike and the parts meet without cracks. Meshes with wide_indices are split however
// few their vertices (max_vertices is taken as at most 65536). Throws std::invalid_argument below 4.
void split_meshes(RenderScene* scene, uint32_t max_vertices);

}  // namespace htx::host
