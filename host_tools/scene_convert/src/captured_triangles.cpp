#include "htx/host/captured_triangles.hpp"

#include "htx/hal/regs.h"

namespace htx::host {

namespace {

uint32_t state_field(uint32_t word, uint32_t pos, uint32_t mask) { return (word & mask) >> pos; }

void capture(void* context, uint32_t state_word, const uint32_t* words) {
  auto* out = static_cast<std::vector<CapturedTriangle>*>(context);
  CapturedTriangle t;
  t.state_word = state_word;
  fw::unpack_triangle(words, &t.record);
  out->push_back(t);
}

}  // namespace

render::TriangleSink capture_sink(std::vector<CapturedTriangle>* out) { return render::TriangleSink{capture, out}; }

TriState from_state_word(uint32_t w) {
  TriState s;
  s.method = static_cast<Method>(state_field(w, RASTER_STATE_METHOD_Pos, RASTER_STATE_METHOD_Msk));
  s.subdiv_n = state_field(w, RASTER_STATE_SUBDIV_N_Pos, RASTER_STATE_SUBDIV_N_Msk);
  s.filter = static_cast<Filter>(state_field(w, RASTER_STATE_FILTER_Pos, RASTER_STATE_FILTER_Msk));
  s.wrap_u = static_cast<Wrap>(state_field(w, RASTER_STATE_WRAP_U_Pos, RASTER_STATE_WRAP_U_Msk));
  s.wrap_v = static_cast<Wrap>(state_field(w, RASTER_STATE_WRAP_V_Pos, RASTER_STATE_WRAP_V_Msk));
  s.depth_func = static_cast<DepthFunc>(state_field(w, RASTER_STATE_DEPTH_FUNC_Pos, RASTER_STATE_DEPTH_FUNC_Msk));
  s.depth_write = state_field(w, RASTER_STATE_DEPTH_WRITE_Pos, RASTER_STATE_DEPTH_WRITE_Msk) != 0;
  s.textured = state_field(w, RASTER_STATE_TEXTURED_Pos, RASTER_STATE_TEXTURED_Msk) != 0;
  s.gouraud = state_field(w, RASTER_STATE_GOURAUD_Pos, RASTER_STATE_GOURAUD_Msk) != 0;
  s.combine = static_cast<Combine>(state_field(w, RASTER_STATE_COMBINE_Pos, RASTER_STATE_COMBINE_Msk));
  s.texture = static_cast<int>(state_field(w, RASTER_STATE_TEXTURE_Pos, RASTER_STATE_TEXTURE_Msk));
  return s;
}

}  // namespace htx::host
