// Helpers the built-in scenes use to build meshes: vertices, oriented triangles, subdivided quads.
#pragma once

#include <string>

#include "htx/model/scene.hpp"

namespace htx {

Vertex make_vertex(Vec3 pos, double s, double t, double r = 1, double g = 1, double b = 1, double a = 1);

// Appends a triangle (counter-clockwise seen from its front).
void add_triangle(Mesh& mesh, const Vertex& a, const Vertex& b, const Vertex& c);

// Appends a triangle turned so that its front faces the point `viewer`.
void add_triangle_facing(Mesh& mesh, const Vertex& a, const Vertex& b, const Vertex& c, Vec3 viewer);

// Appends the parallelogram origin + [0,1]*edge_u + [0,1]*edge_v as nu x nv quads (two triangles
// each) with texture coordinates bilinear from (s0, t0) at origin to (s1, t1) at the far corner.
// The front side is the one edge_u x edge_v points to.
void add_grid(Mesh& mesh, Vec3 origin, Vec3 edge_u, Vec3 edge_v, int nu, int nv, double s0, double t0,
              double s1, double t1);

Mesh make_mesh(const std::string& name, int texture);

}  // namespace htx
