#include "htx/render/frame.h"

#include "htx/hal/raster.h"

namespace htx::render {

FrameStatus render_frame(const FrameParams& frame, const FrameClear& clear, const Mat4& view_proj, const Mesh* meshes,
                         uint32_t count, VertexCache* cache, uint32_t max_polls, DrawStats* stats,
                         DrawStatus* mesh_status) {
  const uint32_t w = static_cast<uint32_t>(frame.viewport.width), h = static_cast<uint32_t>(frame.viewport.height);
  hal::raster_configure(w, h, w);
  hal::raster_clear(clear.enabled, clear.color, clear.enabled, clear.depth);
  if (!hal::raster_wait_idle(max_polls)) return kFrameTimeout;
  hal::raster_reset_counters();
  const TriangleSink sink = raster_fifo_sink();
  for (uint32_t i = 0; i < count; ++i) {
    const DrawStatus st = draw_mesh(frame, view_proj, meshes[i], cache, sink, stats);
    if (st != kDrawOk) {
      if (mesh_status) *mesh_status = st;
      return kFrameBadMesh;
    }
  }
  return hal::raster_wait_idle(max_polls) ? kFrameOk : kFrameTimeout;
}

}  // namespace htx::render
