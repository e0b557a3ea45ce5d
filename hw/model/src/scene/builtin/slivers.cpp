// `slivers`: a fan of very thin triangles sharing a centre (every shared edge must be drawn exactly
// once) on a tilted disc, plus needles narrower than a pixel.
#include <cmath>

#include "htx/model/random.hpp"
#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_slivers(SceneParams& p) {
  const int spokes = p.integer("spokes", 512, 8, 8192);
  const int needles = p.integer("needles", 64, 0, 4096);
  const int seed = p.integer("seed", 1, 0, 1 << 30);
  Scene s;
  s.textures.push_back(default_checker());
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.near_plane = 0.1;
  s.camera.far_plane = 20;
  Mesh fan = make_mesh("fan", 0);
  const Vertex centre = make_vertex({0, 0, 0}, 0.5, 0.5);
  auto rim = [&](int k) {
    const double a = 2 * kPi * k / spokes;
    return make_vertex({1.6 * std::cos(a), 1.6 * std::sin(a), 0}, 0.5 + 2 * std::cos(a), 0.5 + 2 * std::sin(a),
                       0.5 + 0.5 * std::cos(a), 0.5 + 0.5 * std::sin(a), 1);
  };
  for (int k = 0; k < spokes; ++k) add_triangle(fan, centre, rim(k), rim(k + 1));
  fan.model = translate({0, 0, -3}) * rotate({1, 0, 0}, radians(-35));
  s.meshes.push_back(std::move(fan));

  Mesh needle = make_mesh("needles", 0);
  SplitMix64 rng(static_cast<uint64_t>(seed));
  for (int k = 0; k < needles; ++k) {
    const double a = rng.uniform(0, 2 * kPi), width = rng.uniform(0.0005, 0.004);
    const Vec3 c{rng.uniform(-1.5, 1.5), rng.uniform(-1.1, 1.1), rng.uniform(-4, -2.5)};
    const Vec3 dir{std::cos(a), std::sin(a), 0}, side{-std::sin(a), std::cos(a), 0};
    add_triangle_facing(needle, make_vertex(c + dir * 0.8, 0, 0), make_vertex(c - dir * 0.8 + side * width, 3, 0.1),
                        make_vertex(c - dir * 0.8 - side * width, 3, 0.2), {0, 0, 0});
  }
  s.meshes.push_back(std::move(needle));
  return s;
}

}  // namespace htx::scenes
