// `pan`: a magnified, slightly tilted texture panned by `step`/256 texel: consecutive steps must
// move the sampled coordinates by exactly 1/256 texel.
#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_pan(SceneParams& p) {
  const int step = p.integer("step", 1, -65536, 65536, "1/256 texel");
  const double tilt = p.number("tilt", 20, 0, 70, "deg");
  Scene s;
  s.textures.push_back(gradient_texture(TexFormat::RGB565, 5));  // 32x32: about 9 pixels per texel
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.near_plane = 0.1;
  s.camera.far_plane = 20;
  Mesh m = make_mesh("pan", 0);
  const double ds = step / 256.0 / 32.0;
  add_grid(m, {-1.6, -1.2, 0}, {3.2, 0, 0}, {0, 2.4, 0}, 2, 2, ds, ds, 1 + ds, 1 + ds);
  m.model = translate({0, 0, -2.2}) * rotate({1, 0, 0}, radians(-tilt));
  s.meshes.push_back(std::move(m));
  return s;
}

}  // namespace htx::scenes
