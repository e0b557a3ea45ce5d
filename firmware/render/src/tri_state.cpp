#include "htx/render/tri_state.h"

#include "htx/hal/regs.h"

namespace htx::render {

namespace {

uint32_t field(uint32_t value, uint32_t pos, uint32_t mask) { return (value << pos) & mask; }

}  // namespace

uint32_t pack_state_word(const TriState& s, uint8_t method) {
  return field(method, RASTER_STATE_METHOD_Pos, RASTER_STATE_METHOD_Msk) |
         field(s.subdiv_n, RASTER_STATE_SUBDIV_N_Pos, RASTER_STATE_SUBDIV_N_Msk) |
         field(s.filter, RASTER_STATE_FILTER_Pos, RASTER_STATE_FILTER_Msk) |
         field(s.wrap_u, RASTER_STATE_WRAP_U_Pos, RASTER_STATE_WRAP_U_Msk) |
         field(s.wrap_v, RASTER_STATE_WRAP_V_Pos, RASTER_STATE_WRAP_V_Msk) |
         field(s.depth_func, RASTER_STATE_DEPTH_FUNC_Pos, RASTER_STATE_DEPTH_FUNC_Msk) |
         field(s.depth_write ? 1u : 0u, RASTER_STATE_DEPTH_WRITE_Pos, RASTER_STATE_DEPTH_WRITE_Msk) |
         field(s.textured ? 1u : 0u, RASTER_STATE_TEXTURED_Pos, RASTER_STATE_TEXTURED_Msk) |
         field(s.gouraud ? 1u : 0u, RASTER_STATE_GOURAUD_Pos, RASTER_STATE_GOURAUD_Msk) |
         field(s.combine, RASTER_STATE_COMBINE_Pos, RASTER_STATE_COMBINE_Msk) |
         field(s.texture, RASTER_STATE_TEXTURE_Pos, RASTER_STATE_TEXTURE_Msk);
}

}  // namespace htx::render
