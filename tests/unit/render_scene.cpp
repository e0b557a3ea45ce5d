#include "render_scene.hpp"

#include "htx/hal/regs.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace htx::test {

int32_t to_q16(double x) {
  const double r = std::floor(x * 65536.0 + 0.5);
  if (!(r >= -2147483648.0 && r <= 2147483647.0))
    throw std::out_of_range("value " + std::to_string(x) + " does not fit Q16.16");
  return static_cast<int32_t>(r);
}

render::Mat4 to_mat4_fx(const Mat4& m) {
  double largest = 0;
  for (const auto& row : m.m)
    for (size_t j = 0; j < 3; ++j) largest = std::max(largest, std::fabs(row[j]));
  render::Mat4 r{};
  r.frac = render::kMatMaxFrac;
  while (r.frac > render::kMatMinFrac && std::ldexp(largest, r.frac) >= std::ldexp(1.0, 29)) --r.frac;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double e = m.m[static_cast<size_t>(i)][static_cast<size_t>(j)];
      if (j == 3) {
        r.m[i][j] = to_q16(e);
      } else {
        const double q = std::floor(std::ldexp(e, r.frac) + 0.5);
        if (!(q >= -2147483648.0 && q <= 2147483647.0)) throw std::out_of_range("matrix entry out of range");
        r.m[i][j] = static_cast<int32_t>(q);
      }
    }
  return r;
}

render::TriState to_render_state(const TriState& s) {
  render::TriState r;
  r.method = s.method == Method::Auto ? static_cast<uint8_t>(render::kMethodAuto) : static_cast<uint8_t>(s.method);
  r.subdiv_n = static_cast<uint8_t>(s.subdiv_n);
  r.filter = static_cast<uint8_t>(s.filter);
  r.wrap_u = static_cast<uint8_t>(s.wrap_u);
  r.wrap_v = static_cast<uint8_t>(s.wrap_v);
  r.depth_func = static_cast<uint8_t>(s.depth_func);
  r.depth_write = s.depth_write;
  r.textured = s.textured;
  r.gouraud = s.gouraud;
  r.combine = static_cast<uint8_t>(s.combine);
  r.texture = static_cast<uint8_t>(s.texture);
  return r;
}

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

uint32_t channel8(double c) {
  const double k = std::floor(std::clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return static_cast<uint32_t>(k);
}

void capture(void* context, uint32_t state_word, const uint32_t* words) {
  auto* out = static_cast<std::vector<CapturedTriangle>*>(context);
  CapturedTriangle t;
  t.state_word = state_word;
  fw::unpack_triangle(words, &t.record);
  out->push_back(t);
}

}  // namespace

RenderScene to_render_scene(const Scene& scene, int width, int height) {
  RenderScene out;
  out.width = width;
  out.height = height;
  out.cull_backfaces = scene.cull_backfaces;
  const double aspect = scene.camera.aspect > 0 ? scene.camera.aspect : static_cast<double>(width) / height;
  out.view_proj = to_mat4_fx(scene.camera.projection(aspect) * scene.camera.view());
  out.meshes.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& src = scene.meshes[m];
    RenderScene::MeshData& d = out.meshes[m];
    if (src.vertices.size() > 65536) throw std::out_of_range("mesh '" + src.name + "' has more than 65536 vertices");
    for (const Vertex& v : src.vertices) {
      render::MeshVertex mv{};
      mv.x = to_q16(v.pos.x);
      mv.y = to_q16(v.pos.y);
      mv.z = to_q16(v.pos.z);
      mv.s = to_q16(v.s);
      mv.t = to_q16(v.t);
      mv.rgba = channel8(v.r) | (channel8(v.g) << 8) | (channel8(v.b) << 16) | (channel8(v.a) << 24);
      d.vertices.push_back(mv);
    }
    for (const auto& tri : src.triangles)
      for (uint32_t i : tri) d.indices.push_back(static_cast<uint16_t>(i));
    d.mesh.vertices = d.vertices.data();
    d.mesh.vertex_count = static_cast<uint32_t>(d.vertices.size());
    d.mesh.indices = d.indices.data();
    d.mesh.triangle_count = static_cast<uint32_t>(src.triangles.size());
    d.mesh.model = to_mat4_fx(src.model);
    d.mesh.position_bits = static_cast<int8_t>(render::mesh_position_bits(d.vertices.data(), d.mesh.vertex_count));
    d.mesh.state = to_render_state(src.state);
    if (src.state.textured && src.state.texture >= 0 && static_cast<size_t>(src.state.texture) < scene.textures.size()) {
      const Texture& t = scene.textures[static_cast<size_t>(src.state.texture)];
      d.mesh.tex.log2_width = static_cast<uint8_t>(t.log2_width);
      d.mesh.tex.log2_height = static_cast<uint8_t>(t.log2_height);
    }
  }
  return out;
}

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
        render::draw_mesh(frame, scene.view_proj, d.mesh, &cache, render::TriangleSink{capture, &out}, &local);
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
