#include "htx/model/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace htx {

double clip_plane_distance(const ClipVertex& v, int plane) {
  switch (plane) {
    case 0: return v.pos.w + v.pos.x;
    case 1: return v.pos.w - v.pos.x;
    case 2: return v.pos.w + v.pos.y;
    case 3: return v.pos.w - v.pos.y;
    case 4: return v.pos.w + v.pos.z;
    default: return v.pos.w - v.pos.z;
  }
}

namespace {

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
  auto mix = [t](double p, double q) { return p + (q - p) * t; };
  ClipVertex r;
  r.pos = {mix(a.pos.x, b.pos.x), mix(a.pos.y, b.pos.y), mix(a.pos.z, b.pos.z), mix(a.pos.w, b.pos.w)};
  r.s = mix(a.s, b.s);
  r.t = mix(a.t, b.t);
  r.r = mix(a.r, b.r);
  r.g = mix(a.g, b.g);
  r.b = mix(a.b, b.b);
  r.a = mix(a.a, b.a);
  return r;
}

// The point where edge (inside -> outside) crosses the plane; computed from the inside end only,
// so both triangles sharing the edge get the same bits.
ClipVertex intersect(const ClipVertex& inside, const ClipVertex& outside, int plane) {
  const double di = clip_plane_distance(inside, plane);
  const double d_o = clip_plane_distance(outside, plane);
  return lerp(inside, outside, di / (di - d_o));
}

std::vector<ClipVertex> clip_against(const std::vector<ClipVertex>& poly, int plane) {
  std::vector<ClipVertex> out;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const ClipVertex& cur = poly[i];
    const ClipVertex& next = poly[(i + 1) % n];
    const bool cur_in = clip_plane_distance(cur, plane) >= 0;
    const bool next_in = clip_plane_distance(next, plane) >= 0;
    if (cur_in) out.push_back(cur);
    if (cur_in && !next_in) out.push_back(intersect(cur, next, plane));
    if (!cur_in && next_in) out.push_back(intersect(next, cur, plane));
  }
  return out;
}

double snap(double x) {
  constexpr double k = 1 << kSubpixelBits;
  return std::nearbyint(x * k) / k;
}

}  // namespace

std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon) {
  std::vector<ClipVertex> poly = polygon;
  for (int plane = 0; plane < 6 && poly.size() >= 3; ++plane) poly = clip_against(poly, plane);
  if (poly.size() < 3) return {};
  // The planes imply w >= |z| >= 0; a vertex at w = 0 can only come from a degenerate input (all of
  // x, y, z, w zero), and such a polygon is dropped rather than divided by zero.
  for (const ClipVertex& v : poly)
    if (!(v.pos.w > 0)) return {};
  return poly;
}

ScreenVertex to_screen(const ClipVertex& v, int width, int height, double tex_width, double tex_height) {
  const double inv_w = 1.0 / v.pos.w;
  ScreenVertex s;
  s.x = snap((v.pos.x * inv_w + 1.0) * 0.5 * width);
  s.y = snap((1.0 - v.pos.y * inv_w) * 0.5 * height);
  s.z = std::clamp((v.pos.z * inv_w + 1.0) * 0.5, 0.0, 1.0);
  s.w = v.pos.w;
  s.u = v.s * tex_width;
  s.v = v.t * tex_height;
  s.r = v.r;
  s.g = v.g;
  s.b = v.b;
  s.a = v.a;
  return s;
}

double screen_area2(const ScreenTri& t) {
  const ScreenVertex &a = t.v[0], &b = t.v[1], &c = t.v[2];
  return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

ScreenScene prepare_screen_scene(const Scene& scene, int width, int height) {
  if (width < 1 || height < 1 || width > kMaxScreenSize || height > kMaxScreenSize)
    throw std::invalid_argument("screen size " + std::to_string(width) + "x" + std::to_string(height) +
                                " out of range 1.." + std::to_string(kMaxScreenSize));
  ScreenScene out;
  out.name = scene.name;
  out.width = width;
  out.height = height;
  out.textures = scene.textures;
  out.clear_color = scene.clear_color;

  const Mat4 view_proj =
      scene.camera.projection(scene.camera.aspect > 0 ? scene.camera.aspect
                                                       : static_cast<double>(width) / height) * scene.camera.view();
  for (size_t mesh_index = 0; mesh_index < scene.meshes.size(); ++mesh_index) {
    const Mesh& mesh = scene.meshes[mesh_index];
    double tex_w = 1, tex_h = 1;
    if (mesh.state.textured) {
      if (mesh.state.texture < 0 || static_cast<size_t>(mesh.state.texture) >= scene.textures.size())
        throw std::invalid_argument("mesh '" + mesh.name + "' names missing texture " +
                                    std::to_string(mesh.state.texture));
      const Texture& tex = scene.textures[static_cast<size_t>(mesh.state.texture)];
      tex_w = std::ldexp(1.0, static_cast<int>(tex.log2_width));
      tex_h = std::ldexp(1.0, static_cast<int>(tex.log2_height));
    }
    const Mat4 mvp = view_proj * mesh.model;
    std::vector<ClipVertex> clip(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Vertex& v = mesh.vertices[i];
      clip[i].pos = mvp * Vec4{v.pos.x, v.pos.y, v.pos.z, 1.0};
      clip[i].s = v.s;
      clip[i].t = v.t;
      clip[i].r = v.r;
      clip[i].g = v.g;
      clip[i].b = v.b;
      clip[i].a = v.a;
    }
    for (const auto& tri : mesh.triangles) {
      for (uint32_t idx : tri)
        if (idx >= clip.size())
          throw std::invalid_argument("mesh '" + mesh.name + "': vertex index " + std::to_string(idx) +
                                      " out of range");
      const std::vector<ClipVertex> poly = clip_polygon({clip[tri[0]], clip[tri[1]], clip[tri[2]]});
      for (size_t k = 1; k + 1 < poly.size(); ++k) {
        ScreenTri st;
        st.state = mesh.state;
        st.mesh = static_cast<int>(mesh_index);
        st.v[0] = to_screen(poly[0], width, height, tex_w, tex_h);
        st.v[1] = to_screen(poly[k], width, height, tex_w, tex_h);
        st.v[2] = to_screen(poly[k + 1], width, height, tex_w, tex_h);
        const double area2 = screen_area2(st);
        if (area2 == 0) continue;                        // degenerate after snapping
        if (scene.cull_backfaces && area2 > 0) continue;  // back face (clockwise in NDC)
        out.tris.push_back(st);
      }
    }
  }
  return out;
}

}  // namespace htx
