// One frame on the raster unit through the HAL: screen set-up, fast clear, the meshes streamed
// through the geometry pipeline into the vertex FIFO, and waiting until everything is drawn.
#pragma once

#include <stdint.h>

#include "htx/render/pipeline.h"

namespace htx::render {

struct FrameClear {
  uint16_t color = 0;          // RGB565
  uint32_t depth = 0xFFFFFFu;  // clipped by the unit to its depth width
  bool enabled = true;         // false: draw over the colour and depth there (a scene in parts)
};

enum FrameStatus : int {
  kFrameOk = 0,
  kFrameBadMesh = 1,   // draw_mesh refused a mesh (stats->... and the status in *mesh_status)
  kFrameTimeout = 2,   // the raster unit did not go idle within max_polls status reads
};

// Draws meshes[0..count) into a width x height framebuffer (stride = width). max_polls bounds each
// wait for the unit to go idle (after the clear and after the last triangle).
FrameStatus render_frame(const FrameParams& frame, const FrameClear& clear, const Mat4& view_proj, const Mesh* meshes,
                         uint32_t count, VertexCache* cache, uint32_t max_polls, DrawStats* stats,
                         DrawStatus* mesh_status);

}  // namespace htx::render
