#include "scenes.hpp"

namespace geombench {

namespace {

using htx::render::Mat4;
using htx::render::MeshVertex;

constexpr int32_t q16(int32_t whole) { return whole * 65536; }

// The matrices of the host's geometry stage for the scenes' default parameters at 320x240, as
// htx::test::to_mat4_fx converts them (linear part with `frac` fraction bits, translation Q16.16).
constexpr Mat4 kCubeViewProj = {{{243022694, 0, 0, 0},
                                 {0, 324030259, 0, 0},
                                 {0, 0, -135638021, 284856},
                                 {0, 0, -134217728, 294912}},
                                27};
constexpr Mat4 kCubeModel = {{{464943848, 0, -268435456, 0},
                              {-113445726, 486570288, -196493761, 0},
                              {243285144, 226891452, 421382230, 0},
                              {0, 0, 0, 65536}},
                             29};
constexpr Mat4 kFloorViewProj = {{{348707886, 0, 0, 0},
                                  {0, 460419047, -64707677, -112407},
                                  {0, -37377679, -265956005, -3985},
                                  {0, -37358995, -265823061, 9121}},
                                 28};
constexpr Mat4 kFloorModel = {{{268435456, 0, 0, 0}, {0, 268435456, 0, 0}, {0, 0, 268435456, 0}, {0, 0, 0, 65536}}, 28};

MeshVertex g_cube_vertices[24];
uint16_t g_cube_indices[36];
MeshVertex g_floor_vertices[81];
uint16_t g_floor_indices[128 * 3];
BenchScene g_scenes[2];

// The host's add_grid: an nu x nv grid of quads from origin along eu and ev (Q16.16), texture
// coordinates from (s0, t0) to (s1, t1), two triangles per quad.
void add_grid(MeshVertex* verts, uint32_t* nverts, uint16_t* idx, uint32_t* ntris, const int32_t origin[3],
              const int32_t eu[3], const int32_t ev[3], int nu, int nv, int32_t s0, int32_t t0, int32_t s1, int32_t t1) {
  const uint32_t base = *nverts;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      MeshVertex& v = verts[(*nverts)++];
      v.x = origin[0] + eu[0] / nu * i + ev[0] / nv * j;
      v.y = origin[1] + eu[1] / nu * i + ev[1] / nv * j;
      v.z = origin[2] + eu[2] / nu * i + ev[2] / nv * j;
      v.s = s0 + (s1 - s0) / nu * i;
      v.t = t0 + (t1 - t0) / nv * j;
      v.rgba = 0xFFFFFFFFu;
    }
  const uint32_t row = static_cast<uint32_t>(nu + 1);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = base + static_cast<uint32_t>(j) * row + static_cast<uint32_t>(i);
      uint16_t* t = idx + 3 * (*ntris);
      t[0] = static_cast<uint16_t>(a);
      t[1] = static_cast<uint16_t>(a + 1);
      t[2] = static_cast<uint16_t>(a + row + 1);
      t[3] = static_cast<uint16_t>(a);
      t[4] = static_cast<uint16_t>(a + row + 1);
      t[5] = static_cast<uint16_t>(a + row);
      *ntris += 2;
    }
}

}  // namespace

const BenchScene* bench_scenes(uint32_t* count) {
  // cube: six faces of a 2x2x2 cube, each mapped once (s, t from 0 to 1).
  static const int32_t faces[6][3][3] = {
      {{-1, -1, 1}, {2, 0, 0}, {0, 2, 0}},   {{1, -1, -1}, {-2, 0, 0}, {0, 2, 0}},
      {{1, -1, 1}, {0, 0, -2}, {0, 2, 0}},   {{-1, -1, -1}, {0, 0, 2}, {0, 2, 0}},
      {{-1, 1, 1}, {2, 0, 0}, {0, 0, -2}},   {{-1, -1, -1}, {2, 0, 0}, {0, 0, 2}}};
  uint32_t nv = 0, nt = 0;
  for (const auto& f : faces) {
    const int32_t o[3] = {q16(f[0][0]), q16(f[0][1]), q16(f[0][2])};
    const int32_t eu[3] = {q16(f[1][0]), q16(f[1][1]), q16(f[1][2])};
    const int32_t ev[3] = {q16(f[2][0]), q16(f[2][1]), q16(f[2][2])};
    add_grid(g_cube_vertices, &nv, g_cube_indices, &nt, o, eu, ev, 1, 1, 0, 0, q16(1), q16(1));
  }
  g_scenes[0] = {"cube", g_cube_vertices, nv, g_cube_indices, nt, kCubeViewProj, kCubeModel};
  // floor: x in [-200, 200], z from 2 to -400, 8x8 quads, s from -50 to 50, t from -0.5 to 100.
  nv = nt = 0;
  const int32_t o[3] = {q16(-200), 0, q16(2)};
  const int32_t eu[3] = {q16(400), 0, 0};
  const int32_t ev[3] = {0, 0, -q16(402)};
  add_grid(g_floor_vertices, &nv, g_floor_indices, &nt, o, eu, ev, 8, 8, q16(-50), -q16(1) / 2, q16(50), q16(100));
  g_scenes[1] = {"floor", g_floor_vertices, nv, g_floor_indices, nt, kFloorViewProj, kFloorModel};
  *count = 2;
  return g_scenes;
}

}  // namespace geombench
