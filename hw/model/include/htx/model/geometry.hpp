// The double-precision geometry stage: model/view/projection, Sutherland-Hodgman clipping against the
// six frustum planes in homogeneous space, perspective divide, viewport, back-face culling.
// The firmware does the same in fixed point; this is the host's (and the reference's) version.
//
// Conventions (docs/scenes.md):
// - Front faces are counter-clockwise in NDC (y up). The screen y axis points down, so a front face
//   has a negative screen_area2(); ScreenTris keep the input vertex order.
// - Screen x, y are snapped to the vertex-record grid of 1/2^kSubpixelBits pixel, so every engine
//   rasterises exactly the same triangle; pixel (i, j) covers [i, i+1) x [j, j+1), origin top-left.
// - u = s * width, v = t * height of the triangle's texture (level-0 texels, OpenGL convention).
// - z = (z_ndc + 1) / 2 in [0, 1]; w is the clip-space w (> 0).
#pragma once

#include <vector>

#include "htx/model/linalg.hpp"
#include "htx/model/scene.hpp"
#include "htx/model/types.hpp"

namespace htx {

inline constexpr int kSubpixelBits = 8;
inline constexpr int kMaxScreenSize = 4096;

// A vertex in homogeneous clip space with the attributes the clipper interpolates.
struct ClipVertex {
  Vec4 pos;
  double s = 0, t = 0;
  double r = 1, g = 1, b = 1, a = 1;
};

// Signed distance-like value of a clip vertex to frustum plane `plane` (0..5: x>=-w, x<=w, y>=-w,
// y<=w, z>=-w, z<=w); the vertex is inside when it is >= 0.
double clip_plane_distance(const ClipVertex& v, int plane);

// Clips a convex polygon against the six frustum planes. New vertices are interpolated linearly in
// clip space (which is perspective-correct for every attribute), always from the inside vertex to
// the outside one, so an edge shared by two triangles is cut at bit-identical points. Returns an
// empty polygon when nothing is left; every returned vertex has w > 0.
std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon);

// Perspective divide and viewport for a clipped vertex (x, y snapped to the subpixel grid).
ScreenVertex to_screen(const ClipVertex& v, int width, int height, double tex_width, double tex_height);

// Twice the signed area of a screen triangle (x right, y down); negative for front faces.
double screen_area2(const ScreenTri& t);

// Runs the whole geometry stage. Throws std::invalid_argument on a bad screen size, an index out of
// range or a textured mesh naming a missing texture.
ScreenScene prepare_screen_scene(const Scene& scene, int width, int height);

}  // namespace htx
