#include "htx/host/render_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace htx::host {

int32_t to_q16(double x) {
  const double r = std::floor(x * 65536.0 + 0.5);
  if (!(r >= -2147483648.0 && r <= 2147483647.0))
    throw std::out_of_range("value " + std::to_string(x) +
                            " does not fit Q16.16 (the firmware's numbers: -32768 to 32767)");
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

uint32_t channel8(double c) {
  const double k = std::floor(std::clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return static_cast<uint32_t>(k);
}

// How errors name a mesh: by its name, or by its place when it has none (an OBJ without `o`).
std::string mesh_label(const Mesh& mesh, size_t index) {
  return mesh.name.empty() ? "mesh " + std::to_string(index) : "mesh '" + mesh.name + "'";
}

}  // namespace

RenderScene to_render_scene(const Scene& scene, int width, int height, bool keep_wide) {
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
    d.source = static_cast<uint32_t>(m);
    const bool wide = src.vertices.size() > 65536;
    if (wide && !keep_wide)
      throw std::out_of_range(mesh_label(src, m) + " has more than 65536 vertices");
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
      for (uint32_t i : tri) {
        if (wide)
          d.wide_indices.push_back(i);
        else
          d.indices.push_back(static_cast<uint16_t>(i));
      }
    d.mesh.vertices = d.vertices.data();
    d.mesh.vertex_count = static_cast<uint32_t>(d.vertices.size());
    d.mesh.indices = wide ? nullptr : d.indices.data();
    d.mesh.triangle_count = static_cast<uint32_t>(src.triangles.size());
    d.mesh.model = to_mat4_fx(src.model);
    const int position_bits = render::mesh_position_bits(d.vertices.data(), d.mesh.vertex_count);
    // The firmware's limit (docs/firmware.md, "Number formats"), checked here so that a scene is
    // refused before it is sent, not by the console after the upload.
    if (position_bits > 14)
      throw std::out_of_range(mesh_label(src, m) +
                              " has a vertex coordinate of 16384 or more (2^14, the firmware's limit)");
    d.mesh.position_bits = static_cast<int8_t>(position_bits);
    d.mesh.state = to_render_state(src.state);
    if (src.state.textured && src.state.texture >= 0 && static_cast<size_t>(src.state.texture) < scene.textures.size()) {
      const Texture& t = scene.textures[static_cast<size_t>(src.state.texture)];
      d.mesh.tex.log2_width = static_cast<uint8_t>(t.log2_width);
      d.mesh.tex.log2_height = static_cast<uint8_t>(t.log2_height);
    }
  }
  return out;
}

void split_meshes(RenderScene* scene, uint32_t max_vertices) {
  if (max_vertices < 4) throw std::invalid_argument("a mesh part needs room for a triangle and its anchor vertex");
  max_vertices = std::min<uint32_t>(max_vertices, 65536);  // a part's indices are 16-bit
  std::vector<RenderScene::MeshData> out;
  for (RenderScene::MeshData& whole : scene->meshes) {
    if (whole.vertices.size() <= max_vertices && whole.wide_indices.empty()) {
      out.push_back(std::move(whole));
      continue;
    }
    if (whole.wide_indices.empty()) whole.wide_indices.assign(whole.indices.begin(), whole.indices.end());
    const int bits = render::mesh_position_bits(whole.vertices.data(), static_cast<uint32_t>(whole.vertices.size()));
    // The vertex whose coordinates need the most integer bits: the anchor of parts that need fewer.
    size_t anchor = 0;
    for (size_t v = 0; v < whole.vertices.size(); ++v)
      if (render::mesh_position_bits(&whole.vertices[v], 1) == bits) {
        anchor = v;
        break;
      }
    std::vector<int32_t> part_index(whole.vertices.size(), -1);  // whole -> part vertex index
    RenderScene::MeshData part;
    const auto finish = [&]() {
      if (part.indices.empty()) return;
      if (render::mesh_position_bits(part.vertices.data(), static_cast<uint32_t>(part.vertices.size())) < bits)
        part.vertices.push_back(whole.vertices[anchor]);
      part.mesh = whole.mesh;
      part.source = whole.source;
      out.push_back(std::move(part));
      part = {};
      std::fill(part_index.begin(), part_index.end(), -1);
    };
    const std::vector<uint32_t>& indices = whole.wide_indices;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      uint32_t fresh = 0;
      for (size_t k = 0; k < 3; ++k)
        if (part_index[indices[t + k]] < 0) ++fresh;
      // One place stays free for the anchor (a repeated index counts twice: harmless).
      if (part.vertices.size() + fresh > max_vertices - 1) finish();
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t i = indices[t + k];
        if (part_index[i] < 0) {
          part_index[i] = static_cast<int32_t>(part.vertices.size());
          part.vertices.push_back(whole.vertices[i]);
        }
        part.indices.push_back(static_cast<uint16_t>(part_index[i]));
      }
    }
    finish();
  }
  // The views point into the moved arrays only now.
  for (RenderScene::MeshData& d : out) {
    d.mesh.vertices = d.vertices.data();
    d.mesh.vertex_count = static_cast<uint32_t>(d.vertices.size());
    d.mesh.indices = d.indices.data();
    d.mesh.triangle_count = static_cast<uint32_t>(d.indices.size() / 3);
    d.mesh.position_bits = static_cast<int8_t>(render::mesh_position_bits(d.vertices.data(), d.mesh.vertex_count));
  }
  scene->meshes = std::move(out);
}

}  // namespace htx::host
