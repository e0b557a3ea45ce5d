// The triangles the firmware render pipeline emits, caught on the host: each one's STATE word and
// vertex record, and the host TriState a STATE word stands for, so that the model can draw what
// the firmware would have sent the raster unit (render_model_records). Used by htx (the texel
// errors of a console's frame) and by the tests that compare the firmware with the model.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/types.hpp"
#include "htx/render/pipeline.h"

namespace htx::host {

struct CapturedTriangle {
  uint32_t state_word = 0;
  fw::TriangleRecord record;
};

// A pipeline sink that appends every triangle to *out.
render::TriangleSink capture_sink(std::vector<CapturedTriangle>* out);

// The host TriState a STATE word (hw/regs/raster.json) stands for.
TriState from_state_word(uint32_t word);

}  // namespace htx::host
