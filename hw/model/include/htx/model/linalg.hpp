// Small double-precision vector and 4x4 matrix types for the host geometry stage.
// Matrices are column-vector convention (p' = M * p), stored row-major: m[row][col].
#pragma once

#include <array>
#include <cmath>

namespace htx {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

struct Vec4 {
  double x = 0, y = 0, z = 0, w = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, double k) { return {a.x * k, a.y * k, a.z * k}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) {
  const double l = length(a);
  return l > 0 ? a * (1.0 / l) : a;
}

struct Mat4 {
  std::array<std::array<double, 4>, 4> m{};

  static Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
  }
};

inline Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

inline Vec4 operator*(const Mat4& a, Vec4 p) {
  const double in[4] = {p.x, p.y, p.z, p.w};
  double out[4];
  for (int i = 0; i < 4; ++i)
    out[i] = a.m[i][0] * in[0] + a.m[i][1] * in[1] + a.m[i][2] * in[2] + a.m[i][3] * in[3];
  return {out[0], out[1], out[2], out[3]};
}

Mat4 translate(Vec3 t);
Mat4 scale(Vec3 s);
// Rotation by `radians` about the unit axis (right-handed).
Mat4 rotate(Vec3 axis, double radians);
// Right-handed view matrix: the camera at `eye` looks at `target`; view space looks down -z.
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);
// OpenGL-style perspective projection: clip w = -z_view; z_ndc in [-1, 1] between near and far.
Mat4 perspective(double fovy_radians, double aspect, double near_plane, double far_plane);

}  // namespace htx
