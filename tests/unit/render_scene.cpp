#include "render_scene.hpp"

#include "htx/hal/regs.h"

#include <stdexcept>
#include <string>

namespace htx::test {

namespace {

uint32_t state_field(uint32_t word, uint32_t pos, uint32_t mask) { return (word & mask) >> pos; }

}  // namespace

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

namespace {

void capture(void* context, uint32_t state_word, const uint32_t* words) {
  auto* out = static_cast<std::vector<CapturedTriangle>*>(context);
  CapturedTriangle t;
  t.state_word = state_word;
  fw::unpack_triangle(words, &t.record);
  out->push_back(t);
}

}  // namespace

render::TriangleSink capture_sink(std::vector<CapturedTriangle>* out) { return render::TriangleSink{capture, out}; }

std::vector<CapturedTriangle> draw_scene(const RenderScene& scene, const fw::RecordFormat& format,
                                         uint32_t methods_built, render::DrawStats* stats) {
  std::vector<CapturedTriangle> out;
  render::FrameParams frame;
  frame.viewport = {scene.width, scene.height};
  frame.format = format;
  frame.methods_built = methods_built;
  frame.cull_backfaces = scene.cull_backfaces;
  render::DrawStats local;
  for (const RenderScene::MeshData& d : scene.meshes) {
    std::vector<render::ClipVert> clip(d.vertices.size());
    std::vector<render::ScreenVert> screen(d.vertices.size());
    std::vector<uint8_t> codes(d.vertices.size());
    render::VertexCache cache{clip.data(), screen.data(), codes.data(), static_cast<uint32_t>(d.vertices.size())};
    const render::DrawStatus st =
        render::draw_mesh(frame, scene.view_proj, d.mesh, &cache, capture_sink(&out), &local);
    if (st != render::kDrawOk) throw std::runtime_error("draw_mesh failed with status " + std::to_string(st));
  }
  if (stats) *stats = local;
  return out;
}

std::vector<CapturedTriangle> split_fifo_stream(const std::vector<uint32_t>& words) {
  constexpr size_t n = 1 + fw::kTriangleWords;
  if (words.size() % n != 0)
    throw std::invalid_argument("FIFO stream of " + std::to_string(words.size()) + " words is not whole triangles");
  std::vector<CapturedTriangle> out;
  for (size_t i = 0; i < words.size(); i += n) {
    CapturedTriangle t;
    t.state_word = words[i];
    fw::unpack_triangle(&words[i + 1], &t.record);
    out.push_back(t);
  }
  return out;
}

}  // namespace htx::test
