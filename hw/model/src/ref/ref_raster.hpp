// Exact coverage of one screen triangle: pixel centres at +0.5, top-left fill rule, evaluated with
// exact orientation predicates. Independent of the triangle's winding.
#pragma once

#include <array>

#include "htx/model/types.hpp"

namespace htx::ref {

// Screen-space setup of a triangle: barycentric planes for interpolation and the screen box.
struct TriSetup {
  bool empty = true;           // zero area or entirely off screen
  std::array<double, 2> p[3];  // vertices, reordered so that the edge functions are positive inside
  int order[3] = {0, 1, 2};    // p[k] is input vertex order[k]
  double area2 = 0;            // twice the area (> 0)
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;  // inclusive pixel box clipped to the screen
  bool include_edge[3] = {};   // edge k (p[k] -> p[k+1]) is a top or left edge
};

TriSetup setup_triangle(const ScreenTri& tri, int width, int height);

// Whether the centre of pixel (i, j) is covered under the top-left rule.
bool covers(const TriSetup& s, int i, int j);

// Unnormalised barycentric weights of the input vertices at a point (edge functions of the opposite
// edges, summing to area2) and their screen derivatives. Kept unnormalised so that a ratio of
// weighted sums rounds once: with vertices on the subpixel grid the edge functions at pixel centres
// are exact, and an exactly representable quotient (an exact tie) comes out exact.
struct Barycentric {
  double l[3];
  double dx[3];
  double dy[3];
};
Barycentric barycentric(const TriSetup& s, double x, double y);

}  // namespace htx::ref
