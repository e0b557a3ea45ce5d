// `randmesh`: random closed meshes (convex hulls of random points on random ellipsoids), seeded.
// Their front faces cover each silhouette exactly once, which the fill-rule tests rely on.
#include <cmath>

#include "../convex_hull.hpp"
#include "htx/model/random.hpp"
#include "builtin_makers.hpp"

namespace htx::scenes {

Scene make_randmesh(SceneParams& p) {
  const int seed = p.integer("seed", 1, 0, 1 << 30);
  const int count = p.integer("count", 4, 1, 64, "meshes");
  const int points = p.integer("points", 48, 4, 4000, "a mesh");
  Scene s;
  s.textures.push_back(default_checker());
  s.camera.eye = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.near_plane = 0.1;
  SplitMix64 rng(static_cast<uint64_t>(seed) * 0x2545F4914F6CDD1Dull + 17);
  int cols = 1;
  while (cols * cols < count) ++cols;
  const double distance = 3.2 * cols;
  s.camera.far_plane = distance + 10;
  for (int k = 0; k < count; ++k) {
    const Vec3 axes{rng.uniform(0.5, 1.0), rng.uniform(0.5, 1.0), rng.uniform(0.5, 1.0)};
    std::vector<Vec3> pts;
    Mesh m = make_mesh("hull" + std::to_string(k), 0);
    for (int i = 0; i < points; ++i) {
      // A uniform direction, scaled onto the ellipsoid: every point is a hull vertex.
      const double z = rng.uniform(-1, 1), a = rng.uniform(0, 2 * kPi), rr = std::sqrt(1 - z * z);
      const Vec3 d{rr * std::cos(a) * axes.x, rr * std::sin(a) * axes.y, z * axes.z};
      pts.push_back(d);
      m.vertices.push_back(make_vertex(d, 2 * d.x + 0.5, 2 * d.y + 0.5, rng.uniform(0.4, 1), rng.uniform(0.4, 1),
                                       rng.uniform(0.4, 1)));
    }
    m.triangles = convex_hull(pts);
    const double cx = (k % cols - (cols - 1) / 2.0) * 2.3, cy = (k / cols - (cols - 1) / 2.0) * 2.3;
    m.model = translate({cx, cy, -distance}) * rotate({rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)},
                                                       rng.uniform(0, 2 * kPi));
    s.meshes.push_back(std::move(m));
  }
  return s;
}

}  // namespace htx::scenes
