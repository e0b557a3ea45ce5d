#include "htx/model/linalg.hpp"

#include "htx/model/scene.hpp"

namespace htx {

Mat4 translate(Vec3 t) {
  Mat4 r = Mat4::identity();
  r.m[0][3] = t.x;
  r.m[1][3] = t.y;
  r.m[2][3] = t.z;
  return r;
}

Mat4 scale(Vec3 s) {
  Mat4 r = Mat4::identity();
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  return r;
}

Mat4 rotate(Vec3 axis, double radians) {
  const Vec3 a = normalize(axis);
  const double c = std::cos(radians), s = std::sin(radians), k = 1 - c;
  Mat4 r = Mat4::identity();
  r.m[0][0] = c + a.x * a.x * k;
  r.m[0][1] = a.x * a.y * k - a.z * s;
  r.m[0][2] = a.x * a.z * k + a.y * s;
  r.m[1][0] = a.y * a.x * k + a.z * s;
  r.m[1][1] = c + a.y * a.y * k;
  r.m[1][2] = a.y * a.z * k - a.x * s;
  r.m[2][0] = a.z * a.x * k - a.y * s;
  r.m[2][1] = a.z * a.y * k + a.x * s;
  r.m[2][2] = c + a.z * a.z * k;
  return r;
}

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
  const Vec3 f = normalize(target - eye);
  const Vec3 s = normalize(cross(f, up));
  const Vec3 u = cross(s, f);
  Mat4 r = Mat4::identity();
  r.m[0] = {s.x, s.y, s.z, -dot(s, eye)};
  r.m[1] = {u.x, u.y, u.z, -dot(u, eye)};
  r.m[2] = {-f.x, -f.y, -f.z, dot(f, eye)};
  return r;
}

Mat4 perspective(double fovy_radians, double aspect, double near_plane, double far_plane) {
  const double f = 1.0 / std::tan(fovy_radians / 2);
  Mat4 r;
  r.m[0][0] = f / aspect;
  r.m[1][1] = f;
  r.m[2][2] = -(far_plane + near_plane) / (far_plane - near_plane);
  r.m[2][3] = -2 * far_plane * near_plane / (far_plane - near_plane);
  r.m[3][2] = -1;
  return r;
}

Mat4 Camera::view() const { return look_at(eye, target, up); }

Mat4 Camera::projection(double screen_aspect) const {
  return perspective(fovy_radians, screen_aspect, near_plane, far_plane);
}

}  // namespace htx
