// `wrap`: texture coordinates far from the origin (up to +-2^14 texels) with every wrap mode, on
// quads tilted in perspective: the model must keep sub-texel precision at large |u|.
#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_wrap(SceneParams& p) {
  // Texels: the repeat panel's coordinates end at +offset, the mirror panel's start at -offset, the
  // mixed panel has both; the clamp panel stays at -16..80 (so at small offsets it reaches farthest).
  const double offset = p.number("offset", 16384, 0, 16384, "texels");
  const double tilt = p.number("tilt", 35, 0, 80, "deg");  // about the vertical axis
  Scene s;
  s.textures.push_back(gradient_texture(TexFormat::RGB565, 6));
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.near_plane = 0.1;
  s.camera.far_plane = 20;
  struct Panel {
    const char* name;
    double x, y;          // centre
    double u0, v0;        // texel coordinates at the origin corner
    Wrap wu, wv;
  };
  const double span = 48;  // texels across a panel
  const Panel panels[] = {
      {"repeat+", -0.9, 0.6, offset - span, offset - span, Wrap::Repeat, Wrap::Repeat},
      {"mirror-", 0.9, 0.6, -offset, -offset, Wrap::Mirror, Wrap::Mirror},
      {"mixed", -0.9, -0.6, offset - span, -offset, Wrap::Repeat, Wrap::Mirror},
      {"clamp", 0.9, -0.6, -16, -16, Wrap::Clamp, Wrap::Clamp},  // span 48 reaches past both edges
  };
  for (const Panel& pn : panels) {
    Mesh m = make_mesh(pn.name, 0);
    m.state.wrap_u = pn.wu;
    m.state.wrap_v = pn.wv;
    const double k = pn.name[0] == 'c' ? 96.0 / 64 : span / 64;  // the clamp panel spans 96 texels
    add_grid(m, {-0.75, -0.5, 0}, {1.5, 0, 0}, {0, 1.0, 0}, 2, 2, pn.u0 / 64, pn.v0 / 64, pn.u0 / 64 + k,
             pn.v0 / 64 + k);
    m.model = translate({pn.x, pn.y, -3.2}) * rotate({0, 1, 0}, radians(pn.x > 0 ? -tilt : tilt));
    s.meshes.push_back(std::move(m));
  }
  return s;
}

}  // namespace htx::scenes
