// `floor`: a checkerboard plane seen at a grazing angle, reaching to the horizon: strong
// minification and large depth ratios near the top, magnification at the bottom.
#include <cmath>

#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_floor(SceneParams& p) {
  const double pitch = p.number("pitch", 8, 0.5, 60, "deg down");
  const double height = p.number("height", 1, 0.05, 10, "eye height");  // above the plane
  const int grid = p.integer("grid", 8, 1, 64, "quads a side");
  Scene s;
  s.textures.push_back(default_checker());
  s.camera.eye = {0, height, 0};
  s.camera.target = {0, height - std::tan(radians(pitch)), -1};
  s.camera.near_plane = 0.1;
  s.camera.far_plane = 400;
  // x in [-200, 200], z in [-400, 2]; one texture repeat per 4 units (|u| up to 3200 texels).
  Mesh m = make_mesh("floor", 0);
  add_grid(m, {-200, 0, 2}, {400, 0, 0}, {0, 0, -402}, grid, grid, -50, -0.5, 50, 100);
  s.meshes.push_back(std::move(m));
  return s;
}

}  // namespace htx::scenes
