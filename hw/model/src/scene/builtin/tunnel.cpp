// `tunnel`: the camera inside a long textured cylinder, looking slightly off its axis: every
// direction of texture gradient at once, depth ratios up to the far end, Gouraud-darkened with depth.
#include <cmath>

#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_tunnel(SceneParams& p) {
  const int segments = p.integer("segments", 16, 3, 256, "around");
  const int rings = p.integer("rings", 24, 1, 256, "along");
  const double length = p.number("length", 60, 1, 1000);
  Scene s;
  s.textures.push_back(checkerboard_texture(TexFormat::RGB565, 6, 3, kYellow, kRed));
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0.12, 0.06, -1};
  s.camera.near_plane = 0.05;
  s.camera.far_plane = length + 10;
  Mesh m = make_mesh("tunnel", 0);
  auto point = [&](int k, int j) {
    const double a = 2 * kPi * k / segments;
    const double z = 1 - (length + 1) * j / rings;
    const double shade = 1.0 - 0.7 * j / rings;  // darker with distance (Gouraud modulate)
    return make_vertex({std::cos(a), std::sin(a), z}, 4.0 * k / segments, (1 - z) / 2, shade, shade, shade);
  };
  for (int j = 0; j < rings; ++j)
    for (int k = 0; k < segments; ++k) {
      // Counter-clockwise seen from inside: around the axis, then away from the camera.
      const Vertex a = point(k, j), b = point(k + 1, j), c = point(k + 1, j + 1), d = point(k, j + 1);
      add_triangle(m, a, b, c);
      add_triangle(m, a, c, d);
    }
  s.meshes.push_back(std::move(m));
  return s;
}

}  // namespace htx::scenes
