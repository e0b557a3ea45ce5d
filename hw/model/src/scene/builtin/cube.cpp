// `cube`: reference 002's validation scene, a cube in perspective with a 64x64 checkerboard mapped
// once onto every face.
#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_cube(SceneParams& p) {
  const double yaw = p.number("yaw", 30, -360, 360, "deg");
  const double pitch = p.number("pitch", 25, -90, 90, "deg");
  const double distance = p.number("distance", 4.5, 2.0, 100);
  Scene s;
  s.textures.push_back(default_checker());
  s.camera.eye = {0, 0, distance};
  s.camera.target = {0, 0, 0};
  s.camera.fovy_radians = radians(45);
  s.camera.near_plane = 0.1;
  s.camera.far_plane = 2 * distance + 10;
  Mesh m = make_mesh("cube", 0);
  // Each face: origin corner and two edges whose cross product is the outward normal.
  add_grid(m, {-1, -1, 1}, {2, 0, 0}, {0, 2, 0}, 1, 1, 0, 0, 1, 1);    // +z
  add_grid(m, {1, -1, -1}, {-2, 0, 0}, {0, 2, 0}, 1, 1, 0, 0, 1, 1);   // -z
  add_grid(m, {1, -1, 1}, {0, 0, -2}, {0, 2, 0}, 1, 1, 0, 0, 1, 1);    // +x
  add_grid(m, {-1, -1, -1}, {0, 0, 2}, {0, 2, 0}, 1, 1, 0, 0, 1, 1);   // -x
  add_grid(m, {-1, 1, 1}, {2, 0, 0}, {0, 0, -2}, 1, 1, 0, 0, 1, 1);    // +y
  add_grid(m, {-1, -1, -1}, {2, 0, 0}, {0, 0, 2}, 1, 1, 0, 0, 1, 1);   // -y
  m.model = rotate({1, 0, 0}, radians(pitch)) * rotate({0, 1, 0}, radians(-yaw));
  s.meshes.push_back(std::move(m));
  return s;
}

}  // namespace htx::scenes
