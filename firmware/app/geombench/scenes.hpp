// The vertices of the built-in `cube` and `floor` scenes (hw/model/src/scene/builtin) in the
// firmware's formats, with their view-projection and model matrices for a 320x240 screen.
#pragma once

#include <stdint.h>

#include "htx/render/pipeline.h"

namespace geombench {

struct BenchScene {
  const char* name;
  const htx::render::MeshVertex* vertices;
  uint32_t vertex_count;
  const uint16_t* indices;
  uint32_t triangle_count;
  htx::render::Mat4 view_proj;
  htx::render::Mat4 model;
};

// Fills the vertex and index arrays (built at start-up, no heap) and returns the two scenes.
const BenchScene* bench_scenes(uint32_t* count);

}  // namespace geombench
