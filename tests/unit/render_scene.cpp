#include "render_scene.hpp"

#include <stdexcept>
#include <string>

namespace htx::test {

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
