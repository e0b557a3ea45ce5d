// `nearclip`: triangles that cross the near plane (one or two vertices behind the camera, or
// nearly parallel to it), so the clipper must cut them and interpolate attributes at new vertices.
#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_nearclip(SceneParams& p) {
  const double near_plane = p.number("near", 0.5, 0.01, 2);
  Scene s;
  s.textures.push_back(default_checker());
  s.textures.push_back(gradient_texture(TexFormat::RGB565, 6));
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.near_plane = near_plane;
  s.camera.far_plane = 50;
  const Vec3 eye{0, 0, 0};
  auto v = [](double x, double y, double z, double r, double g, double b) {
    return make_vertex({x, y, z}, x / 2, -z / 2, r, g, b);
  };
  Mesh floor = make_mesh("floor", 0);  // from behind the camera to far ahead
  add_triangle_facing(floor, v(-6, -1, 5, 1, 1, 1), v(6, -1, 5, 1, 0.5, 0.5), v(0, -1, -20, 0.5, 1, 0.5), eye);
  Mesh wall = make_mesh("wall", 1);  // right wall, two vertices behind the camera
  add_triangle_facing(wall, v(1.5, -1, 3, 1, 1, 1), v(1.5, 2, 2, 0.6, 0.6, 1), v(1.5, -0.5, -15, 1, 1, 0.4), eye);
  Mesh pierce = make_mesh("pierce", 1);  // one vertex behind the camera, through the middle
  add_triangle_facing(pierce, v(-0.4, -0.3, 0.2, 1, 0.3, 0.3), v(0.6, -0.2, -3, 0.3, 1, 0.3),
                      v(-0.2, 0.5, -3, 0.3, 0.3, 1), eye);
  Mesh two_behind = make_mesh("two_behind", 0);  // two vertices behind, one ahead
  add_triangle_facing(two_behind, v(-1, 0.3, 1, 1, 1, 1), v(1, 0.4, 2, 0.2, 0.8, 1), v(0.2, -0.1, -2, 1, 0.8, 0.2), eye);
  Mesh grazing = make_mesh("grazing", 1);  // almost parallel to the near plane, straddling it
  add_triangle_facing(grazing, v(-3, -0.8, -near_plane + 0.02, 1, 1, 1), v(3, -0.8, -near_plane - 0.03, 1, 1, 1),
                      v(0, 2, -near_plane + 0.01, 1, 1, 1), eye);
  for (Mesh* m : {&floor, &wall, &pierce, &two_behind, &grazing}) s.meshes.push_back(std::move(*m));
  return s;
}

}  // namespace htx::scenes
