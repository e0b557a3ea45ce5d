// `bigtri`: triangles far larger than the screen (vertices hundreds of screen widths away, some
// behind the camera): clipping and traversal must stay exact and bounded.
#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_bigtri(SceneParams& p) {
  const double size = p.number("size", 1000, 10, 100000);
  Scene s;
  s.textures.push_back(default_checker());
  s.textures.push_back(gradient_texture(TexFormat::RGB565, 6));
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.near_plane = 0.1;
  s.camera.far_plane = 4 * size;
  const Vec3 eye{0, 0, 0};
  // A wall facing the camera, a floor reaching behind it, and a slanted sheet in between.
  Mesh wall = make_mesh("wall", 0);
  add_triangle_facing(wall, make_vertex({-size, -size, -8}, -size / 8, -size / 8),
                      make_vertex({size, -size * 0.7, -8}, size / 8, -size / 8),
                      make_vertex({0.3 * size, size, -8}, 0.3 * size / 8, size / 8), eye);
  Mesh floor = make_mesh("floor", 1);
  floor.state.wrap_u = Wrap::Mirror;
  add_triangle_facing(floor, make_vertex({-size, -1.5, size}, -size / 16, 0, 1, 0.6, 0.6),
                      make_vertex({size, -1.5, size}, size / 16, 0, 0.6, 1, 0.6),
                      make_vertex({0, -1.5, -size}, 0, size / 8, 0.6, 0.6, 1), eye);
  Mesh slant = make_mesh("slant", 0);
  slant.state.depth_func = DepthFunc::LEqual;
  add_triangle_facing(slant, make_vertex({-size, size, -3 - size}, 0, 0, 1, 1, 0.5),
                      make_vertex({size, 0.2, -3}, size / 8, 0, 0.5, 1, 1),
                      make_vertex({-size, -size, -3}, 0, size / 8, 1, 0.5, 1), eye);
  for (Mesh* m : {&wall, &floor, &slant}) s.meshes.push_back(std::move(*m));
  return s;
}

}  // namespace htx::scenes
