#include "mesh_builder.hpp"

namespace htx {

Vertex make_vertex(Vec3 pos, double s, double t, double r, double g, double b, double a) {
  Vertex v;
  v.pos = pos;
  v.s = s;
  v.t = t;
  v.r = r;
  v.g = g;
  v.b = b;
  v.a = a;
  return v;
}

void add_triangle(Mesh& mesh, const Vertex& a, const Vertex& b, const Vertex& c) {
  const auto base = static_cast<uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(a);
  mesh.vertices.push_back(b);
  mesh.vertices.push_back(c);
  mesh.triangles.push_back({base, base + 1, base + 2});
}

void add_triangle_facing(Mesh& mesh, const Vertex& a, const Vertex& b, const Vertex& c, Vec3 viewer) {
  const Vec3 n = cross(b.pos - a.pos, c.pos - a.pos);
  if (dot(n, viewer - a.pos) >= 0)
    add_triangle(mesh, a, b, c);
  else
    add_triangle(mesh, a, c, b);
}

void add_grid(Mesh& mesh, Vec3 origin, Vec3 edge_u, Vec3 edge_v, int nu, int nv, double s0, double t0,
              double s1, double t1) {
  const auto base = static_cast<uint32_t>(mesh.vertices.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double fu = static_cast<double>(i) / nu, fv = static_cast<double>(j) / nv;
      mesh.vertices.push_back(
          make_vertex(origin + edge_u * fu + edge_v * fv, s0 + (s1 - s0) * fu, t0 + (t1 - t0) * fv));
    }
  const auto row = static_cast<uint32_t>(nu + 1);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = base + static_cast<uint32_t>(j) * row + static_cast<uint32_t>(i);
      mesh.triangles.push_back({a, a + 1, a + row + 1});
      mesh.triangles.push_back({a, a + row + 1, a + row});
    }
}

Mesh make_mesh(const std::string& name, int texture) {
  Mesh m;
  m.name = name;
  m.state.texture = texture;
  return m;
}

}  // namespace htx
