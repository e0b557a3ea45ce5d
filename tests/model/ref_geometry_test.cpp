// The double geometry stage against hand-computed values: projection, viewport, snapping, culling,
// and the homogeneous clipper (no w <= 0 survives, attributes interpolated at the right point).
#include <gtest/gtest.h>

#include <cmath>

#include "htx/model/geometry.hpp"
#include "htx/model/proc_textures.hpp"
#include "htx/model/scene.hpp"

namespace htx {
namespace {

Vertex vtx(double x, double y, double z, double s = 0, double t = 0) {
  Vertex v;
  v.pos = {x, y, z};
  v.s = s;
  v.t = t;
  return v;
}

// 90 degree vertical field of view, square screen: x_ndc = x / -z, y_ndc = y / -z.
Scene square_scene() {
  Scene s;
  s.camera.fovy_radians = std::acos(-1.0) / 2;
  s.camera.near_plane = 1;
  s.camera.far_plane = 9;
  s.textures.push_back(checkerboard_texture(TexFormat::RGB565, 6, 3, {255, 255, 255, 255}, {0, 0, 0, 255}));
  return s;
}

TEST(RefGeometry, ProjectsAndMapsViewportByHand) {
  Scene s = square_scene();
  Mesh m;
  m.vertices = {vtx(-1, -1, -2, 0, 0), vtx(2, -1, -2, 0.5, 0), vtx(-1, 1, -4, 0, 0.25)};
  m.triangles = {{0, 1, 2}};
  s.meshes.push_back(m);
  const ScreenScene out = prepare_screen_scene(s, 100, 100);
  ASSERT_EQ(out.tris.size(), 1u);
  const ScreenTri& t = out.tris[0];
  // (-1,-1,-2): ndc (-0.5,-0.5) -> x = 0.25*100, y = (1+0.5)/2*100 = 75
  EXPECT_DOUBLE_EQ(t.v[0].x, 25);
  EXPECT_DOUBLE_EQ(t.v[0].y, 75);
  EXPECT_DOUBLE_EQ(t.v[0].w, 2);
  // z_ndc = (-(f+n)/(f-n) z - 2fn/(f-n)) / w = (10/8*2 - 18/8)/2 = 0.125 -> window (1.125)/2
  EXPECT_NEAR(t.v[0].z, 0.5625, 1e-12);
  // (2,-1,-2): ndc (1,-0.5) -> x = 100
  EXPECT_DOUBLE_EQ(t.v[1].x, 100);
  EXPECT_DOUBLE_EQ(t.v[1].u, 32);  // s = 0.5 of 64 texels
  // (-1,1,-4): ndc (-0.25, 0.25) -> x = 37.5, y = 37.5
  EXPECT_DOUBLE_EQ(t.v[2].x, 37.5);
  EXPECT_DOUBLE_EQ(t.v[2].y, 37.5);
  EXPECT_DOUBLE_EQ(t.v[2].v, 16);
  EXPECT_DOUBLE_EQ(t.v[2].w, 4);
  EXPECT_LT(screen_area2(t), 0);  // front faces are negative in screen space
}

TEST(RefGeometry, SnapsToSubpixelGrid) {
  Scene s = square_scene();
  Mesh m;
  m.vertices = {vtx(-0.3333, -0.7777, -2), vtx(0.91, -0.5, -2), vtx(0.1234567, 0.6, -2)};
  m.triangles = {{0, 1, 2}};
  s.meshes.push_back(m);
  const ScreenScene out = prepare_screen_scene(s, 97, 61);
  ASSERT_EQ(out.tris.size(), 1u);
  for (const ScreenVertex& v : out.tris[0].v) {
    EXPECT_EQ(v.x * 256, std::round(v.x * 256));
    EXPECT_EQ(v.y * 256, std::round(v.y * 256));
  }
  // aspect 97/61: x_ndc = -0.3333 * 61/97 / 2 = -0.1048005 -> x = (1 - 0.1048005) / 2 * 97 = 43.41717...,
  // times 256 = 11114.8, snapped to 11115/256.
  EXPECT_DOUBLE_EQ(out.tris[0].v[0].x, 11115.0 / 256);
}

TEST(RefGeometry, CullsBackFacesUnlessDisabled) {
  Scene s = square_scene();
  Mesh m;
  m.vertices = {vtx(-1, -1, -2), vtx(1, -1, -2), vtx(0, 1, -2)};
  m.triangles = {{0, 1, 2}, {0, 2, 1}};  // front, then the same triangle clockwise
  s.meshes.push_back(m);
  EXPECT_EQ(prepare_screen_scene(s, 64, 64).tris.size(), 1u);
  s.cull_backfaces = false;
  EXPECT_EQ(prepare_screen_scene(s, 64, 64).tris.size(), 2u);
}

TEST(RefGeometry, ClipperCutsNearPlaneAtHandComputedPoint) {
  // a is in front of the eye (w = 1) but nearer than the near plane (z + w = -2); b, c are inside.
  ClipVertex a, b, c;
  a.pos = {0, 0, -3, 1};
  a.s = 1;
  a.r = 0;
  b.pos = {0.5, 0, 1, 3};  // z + w = 4
  b.s = 3;
  b.r = 1;
  c.pos = {-0.5, 0.5, 1, 3};
  c.s = 3;
  c.r = 1;
  const auto poly = clip_polygon({a, b, c});
  ASSERT_EQ(poly.size(), 4u);
  // Edge b -> a crosses at t = 4 / (4 + 2) = 2/3 from b: (1/6, 0, -5/3, 5/3), s = 5/3, r = 1/3.
  bool found = false;
  for (const ClipVertex& v : poly) {
    for (int p = 0; p < 6; ++p) EXPECT_GE(clip_plane_distance(v, p), -1e-12);
    if (std::fabs(v.pos.x - 1.0 / 6) < 1e-12 && std::fabs(v.pos.y) < 1e-12) {
      found = true;
      EXPECT_NEAR(v.pos.z, -5.0 / 3, 1e-12);
      EXPECT_NEAR(v.pos.w, 5.0 / 3, 1e-12);
      EXPECT_NEAR(v.s, 5.0 / 3, 1e-12);
      EXPECT_NEAR(v.r, 1.0 / 3, 1e-12);
    }
  }
  EXPECT_TRUE(found);
}

TEST(RefGeometry, ClipperRemovesVerticesBehindTheEyeAndKeepsAttributesLinear) {
  // Attributes are a fixed linear function of the clip position, so any correct interpolation keeps
  // them on it; a vertex behind the eye (w < 0) must never come out.
  auto attr = [](const Vec4& p) { return 2 * p.x - p.y + 0.5 * p.z + 3 * p.w; };
  ClipVertex a, b, c;
  a.pos = {0.2, 0.1, -3, -1};
  b.pos = {0.5, 0, 1, 3};
  c.pos = {-0.5, 0.5, 1, 3};
  for (ClipVertex* v : {&a, &b, &c}) {
    v->s = attr(v->pos);
    v->t = -attr(v->pos);
  }
  const auto poly = clip_polygon({a, b, c});
  ASSERT_GE(poly.size(), 3u);
  for (const ClipVertex& v : poly) {
    EXPECT_GT(v.pos.w, 0);
    for (int p = 0; p < 6; ++p) EXPECT_GE(clip_plane_distance(v, p), -1e-12);
    EXPECT_NEAR(v.s, attr(v.pos), 1e-12);
    EXPECT_NEAR(v.t, -attr(v.pos), 1e-12);
  }
}

TEST(RefGeometry, ClipperDropsPolygonsEntirelyBehindOrOutside) {
  ClipVertex a, b, c;
  a.pos = {0, 0, 0, -1};
  b.pos = {1, 0, 0, -2};
  c.pos = {0, 1, 0, -1};
  EXPECT_TRUE(clip_polygon({a, b, c}).empty());
  a.pos = {5, 0, 0, 1};
  b.pos = {6, 0, 0, 1};
  c.pos = {5, 1, 0, 1};
  EXPECT_TRUE(clip_polygon({a, b, c}).empty());
}

TEST(RefGeometry, SharedEdgeIsCutAtIdenticalPoints) {
  // Two triangles sharing an edge that crosses the x = w plane, listed in opposite directions.
  ClipVertex p, q, r1, r2;
  p.pos = {0.3, 0.1, 0.2, 1.3};
  q.pos = {7.7, -0.3, 0.1, 2.9};
  r1.pos = {0.1, 0.9, 0.3, 1.7};
  r2.pos = {0.2, -0.9, 0.1, 1.1};
  const auto a = clip_polygon({p, q, r1});
  const auto b = clip_polygon({q, p, r2});
  int shared = 0;
  for (const ClipVertex& u : a)
    for (const ClipVertex& v : b)
      if (u.pos.x == v.pos.x && u.pos.y == v.pos.y && u.pos.z == v.pos.z && u.pos.w == v.pos.w) ++shared;
  EXPECT_EQ(shared, 2);  // p and the cut point on p-q
}

TEST(RefGeometry, NoVertexWithNonPositiveWAfterClipOnNearclipScene) {
  // Random triangles through the eye: every emitted vertex must be in front.
  Scene s = square_scene();
  Mesh m;
  for (int i = 0; i < 200; ++i) {
    const double a = i * 0.37, b = i * 0.91;
    m.vertices.push_back(vtx(std::sin(a) * 3, std::cos(b) * 3, std::sin(a + b) * 6));
  }
  for (uint32_t i = 0; i + 2 < 200; ++i) m.triangles.push_back({i, i + 1, i + 2});
  s.meshes.push_back(m);
  s.cull_backfaces = false;
  const ScreenScene out = prepare_screen_scene(s, 128, 128);
  EXPECT_GT(out.tris.size(), 50u);
  for (const ScreenTri& t : out.tris)
    for (const ScreenVertex& v : t.v) {
      EXPECT_GT(v.w, 0);
      EXPECT_GE(v.x, 0);
      EXPECT_LE(v.x, 128);
      EXPECT_GE(v.y, 0);
      EXPECT_LE(v.y, 128);
      EXPECT_GE(v.z, 0);
      EXPECT_LE(v.z, 1);
    }
}

TEST(RefGeometry, RejectsBadInput) {
  Scene s = square_scene();
  EXPECT_THROW(prepare_screen_scene(s, 0, 10), std::invalid_argument);
  EXPECT_THROW(prepare_screen_scene(s, 10, 5000), std::invalid_argument);
  Mesh m;
  m.vertices = {vtx(0, 0, -2)};
  m.triangles = {{0, 0, 1}};
  s.meshes.push_back(m);
  EXPECT_THROW(prepare_screen_scene(s, 10, 10), std::invalid_argument);
  s.meshes.back().triangles = {{0, 0, 0}};
  s.meshes.back().state.texture = 3;
  EXPECT_THROW(prepare_screen_scene(s, 10, 10), std::invalid_argument);
}

}  // namespace
}  // namespace htx
