// Test support: the triangles a frame streamed into a Verilated raster unit, as vertex records for
// the model. A unit with CAPS.FW_SETUP takes plane records, from which no vertex record can be read
// back: the frame's pipeline then runs again into a capturing sink (it is deterministic), and the
// FIFO's words must equal those records' plane records, word for word, as rtl::FifoRecords (the
// HAL's own conversion, on the host) makes them. Shared by the cosim tests and the system test.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "htx/model/config.hpp"
#include "htx/render/pipeline.h"
#include "htx/rtl/fifo_records.hpp"
#include "render_scene.hpp"

namespace htx::test {

struct FrameRecords {
  std::vector<CapturedTriangle> tris;  // what the pipeline emitted
  uint64_t sent = 0;                   // the triangles the unit was sent (CNT_TRIANGLES)
};

inline FrameRecords frame_records(const std::vector<uint32_t>& fifo, uint32_t caps, const ModelConfig& cfg,
                                  const render::FrameParams& frame, const render::Mat4& view_proj,
                                  const render::Mesh* meshes, uint32_t count, render::VertexCache* cache) {
  const rtl::FifoRecords form(cfg, caps, frame.viewport.width, frame.viewport.height);
  FrameRecords r;
  if (!form.fw_setup()) {
    r.tris = split_fifo_stream(fifo);
    r.sent = r.tris.size();
    return r;
  }
  render::DrawStats stats;
  for (uint32_t i = 0; i < count; ++i)
    if (render::draw_mesh(frame, view_proj, meshes[i], cache, capture_sink(&r.tris), &stats) !=
        render::kDrawOk)
      throw std::runtime_error("frame_records: draw_mesh failed on the second run");
  std::vector<uint32_t> expect;
  for (const CapturedTriangle& t : r.tris) r.sent += form.append(&expect, t.state_word, t.record) ? 1 : 0;
  if (expect != fifo)
    throw std::runtime_error("frame_records: the FIFO's " + std::to_string(fifo.size()) +
                             " words are not the plane records of the pipeline's " + std::to_string(r.tris.size()) +
                             " triangles (" + std::to_string(expect.size()) + " words)");
  return r;
}

}  // namespace htx::test
