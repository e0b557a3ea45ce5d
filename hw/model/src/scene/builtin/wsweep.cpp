// `wsweep`: one triangle whose depth goes from w_near = 1 along its left edge to w_far = r at its
// right apex, with u going from 0 to du. 1/w and u/w then depend on screen x only, so every row
// sees the same u(x), and affine interpolation errs by up to du*(sqrt(r)-1)/(sqrt(r)+1) texels.
// The projection uses a fixed 4:3 aspect so the screen extent of the triangle is known: its left
// edge is at x_ndc = -0.9, its apex at x_ndc = +0.9, y_ndc within +-0.9.
#include <cmath>

#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_wsweep(SceneParams& p) {
  const double r = p.number("r", 10, 1, 1000, "depth ratio");
  const double du = p.number("du", 256, 1, 4096, "texels");  // texels spanned from left edge to apex
  Scene s;
  s.textures.push_back(gradient_texture(TexFormat::RGB565, 6));
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.fovy_radians = radians(60);
  s.camera.aspect = 4.0 / 3.0;
  s.camera.near_plane = 0.5;
  s.camera.far_plane = 2 * r + 1;
  const double f = 1 / std::tan(s.camera.fovy_radians / 2);
  const double sx = s.camera.aspect / f, sy = 1 / f;  // view-space extent per unit depth and NDC unit
  const double wn = 1, wf = r;
  const double s1 = du / 64.0;
  Mesh m = make_mesh("wsweep", 0);
  m.state.wrap_u = Wrap::Repeat;
  add_triangle(m, make_vertex({-0.9 * sx * wn, -0.9 * sy * wn, -wn}, 0, 1),  // left bottom
               make_vertex({0.9 * sx * wf, 0, -wf}, s1, 0.5),               // apex
               make_vertex({-0.9 * sx * wn, 0.9 * sy * wn, -wn}, 0, 0));     // left top
  s.meshes.push_back(std::move(m));
  return s;
}

}  // namespace htx::scenes
