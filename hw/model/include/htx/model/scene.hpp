// The 3D scene as the host (and later the firmware) holds it, before the geometry stage.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "htx/model/linalg.hpp"
#include "htx/model/types.hpp"

namespace htx {

struct Vertex {
  Vec3 pos;                            // object space
  double s = 0, t = 0;                 // normalised texture coordinates (1.0 = one texture width)
  double r = 1, g = 1, b = 1, a = 1;   // colour in [0, 1]
};

// A triangle list sharing one per-triangle state. state.texture indexes Scene::textures.
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into vertices
  Mat4 model = Mat4::identity();                   // object -> world
  TriState state;
};

struct Camera {
  Vec3 eye{0, 0, 0}, target{0, 0, -1}, up{0, 1, 0};
  double fovy_radians = 1.0471975511965976;  // 60 degrees
  double near_plane = 0.1, far_plane = 100.0;
  double aspect = 0;  // width / height of the projection; 0 takes it from the screen size
  Mat4 view() const;
  Mat4 projection(double screen_aspect) const;
};

struct Scene {
  std::string name;
  std::vector<Texture> textures;
  std::vector<Mesh> meshes;
  Camera camera;
  uint16_t clear_color = 0;  // RGB565
  bool cull_backfaces = true;  // front faces are counter-clockwise in NDC
  // What loading changed that the user should hear of (an OBJ's texture drawn from a smaller mip
  // level); the tools print each line.
  std::vector<std::string> notes;
  // The files it was read from (an OBJ, its material libraries and textures; none for a built-in
  // scene), so that a tool can refuse to write an output over one of them.
  std::vector<std::string> sources;
};

}  // namespace htx
