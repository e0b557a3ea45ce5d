// Test support: a host Scene (hw/model) as the firmware render pipeline takes it (Q16.16 meshes and
// matrices), and the triangles the pipeline streams, captured and decoded. Shared by the unit tests
// of firmware/render and the cosim tests.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/scene.hpp"
#include "htx/render/pipeline.h"

namespace htx::test {

int32_t to_q16(double x);  // round(x * 2^16), checked against the Q16.16 range (throws)
// Linear part with the most fraction bits (16..30) its largest entry allows, translation Q16.16.
render::Mat4 to_mat4_fx(const Mat4& m);

// The firmware form of a scene's meshes; owns the arrays the render::Mesh views point at.
struct RenderScene {
  struct MeshData {
    std::vector<render::MeshVertex> vertices;
    std::vector<uint16_t> indices;
    render::Mesh mesh{};
  };
  std::vector<MeshData> meshes;
  render::Mat4 view_proj{};
  int width = 0, height = 0;
  bool cull_backfaces = true;
};

// Converts with the host's camera (projection * view for the screen's aspect). Throws when a
// value leaves Q16.16 or a mesh has more than 65536 vertices.
RenderScene to_render_scene(const Scene& scene, int width, int height);

render::TriState to_render_state(const TriState& s);
// The host TriState a STATE word (hw/regs/raster.json) stands for.
TriState from_state_word(uint32_t word);

struct CapturedTriangle {
  uint32_t state_word = 0;
  fw::TriangleRecord record;
};

// Runs the firmware pipeline over every mesh into a capturing sink.
std::vector<CapturedTriangle> draw_scene(const RenderScene& scene, const fw::RecordFormat& format,
                                         uint32_t methods_built, render::DrawStats* stats = nullptr);

// Splits a FIFO word stream (state word + kTriangleWords per triangle) into triangles; throws on a
// stream whose length is not a whole number of triangles.
std::vector<CapturedTriangle> split_fifo_stream(const std::vector<uint32_t>& words);

}  // namespace htx::test
