// Types shared by every engine: the scene as a renderer sees it, render options, and frames.
// The float64 reference (`ref`) and the bit-accurate model (`model`) both consume a ScreenScene
// produced from a Scene by the double-precision geometry stage (prepare_screen_scene).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace htx {

enum class TexFormat : uint8_t { RGB565, RGBA4444, RGBA8888 };
enum class Wrap : uint8_t { Repeat, Clamp, Mirror };
enum class Filter : uint8_t { Nearest, Bilinear, Trilinear };
// Perspective method, chosen per triangle. Quadratic exists in the model only (for the study).
enum class Method : uint8_t { Affine, Subdiv, RecipLut, RecipNr, DivFree, Quadratic, Auto };
enum class DepthFunc : uint8_t { Never, Less, LEqual, Equal, Greater, Always };

// Whether a fragment at depth z passes against the stored depth (both engines: the reference's
// doubles, the model's fixed-point words).
template <class T>
constexpr bool depth_passes(DepthFunc f, T z, T stored) {
  switch (f) {
    case DepthFunc::Never: return false;
    case DepthFunc::Less: return z < stored;
    case DepthFunc::LEqual: return z <= stored;
    case DepthFunc::Equal: return z == stored;
    case DepthFunc::Greater: return z > stored;
    case DepthFunc::Always: return true;
  }
  return false;
}
enum class Combine : uint8_t { Replace, Modulate };

// A texture with its whole mip chain. Texels are stored packed in their format (RGB565 and RGBA4444
// use the low 16 bits), row-major, level 0 first. Width and height are powers of two, 8..256.
struct Texture {
  TexFormat format = TexFormat::RGB565;
  unsigned log2_width = 6;
  unsigned log2_height = 6;
  std::vector<std::vector<uint32_t>> levels;
};

// Per-triangle state: travels with the triangle through the pipeline.
struct TriState {
  Method method = Method::RecipNr;
  unsigned subdiv_n = 16;  // span length for Method::Subdiv (2..64)
  Filter filter = Filter::Bilinear;
  Wrap wrap_u = Wrap::Repeat;
  Wrap wrap_v = Wrap::Repeat;
  DepthFunc depth_func = DepthFunc::Less;
  bool depth_write = true;
  bool textured = true;
  bool gouraud = true;  // false: flat, colour of vertex 0
  Combine combine = Combine::Modulate;
  int texture = 0;      // index into ScreenScene::textures
};

// A vertex after transform, clip, perspective divide and viewport, in double precision.
struct ScreenVertex {
  double x = 0, y = 0;  // pixels; origin at the top-left corner, pixel centres at +0.5
  double z = 0;         // depth in [0, 1]
  double w = 1;         // clip-space w (> 0 after clipping)
  double u = 0, v = 0;  // texture coordinates in texels of level 0 (u = s * width, OpenGL convention)
  double r = 1, g = 1, b = 1, a = 1;  // colour in [0, 1]
};

struct ScreenTri {
  std::array<ScreenVertex, 3> v;
  TriState state;
  int mesh = 0;  // the scene mesh it comes from (the metrics compare a pixel where both frames show one mesh)
};

struct ScreenScene {
  std::string name;
  int width = 320, height = 240;
  std::vector<Texture> textures;
  std::vector<ScreenTri> tris;
  uint16_t clear_color = 0;  // RGB565
  uint32_t clear_depth = 0xFFFFFFFFu;  // clipped to the configured depth width
};

// Per-pixel record every engine fills for the metrics: what the pixel's texture lookup used.
struct PixelProbe {
  bool covered = false;    // a fragment of a textured triangle passed the depth test here
  double u = 0, v = 0;     // texture coordinate used, in texels of level 0
  int level = 0;           // mip level sampled (the finer one for trilinear)
  double lod = 0;          // level of detail
  uint32_t divfree_steps = 0;
  int mesh = -1;           // the scene mesh of that fragment's triangle (ScreenTri::mesh)
  int tri = -1;            // that triangle's index in the scene's drawing order (ScreenScene::tris,
                           // RecordScene::tris); -1 where the engine does not say (ref)
};

struct Counters {
  uint64_t triangles = 0, fragments = 0, pixels_written = 0;
  uint64_t divfree_steps_total = 0, divfree_steps_max = 0, divfree_cap_hits = 0, divfree_pixels = 0;
  uint64_t cycles = 0;  // engines that model time fill this
  // Triangles the vertex-record encoder refused (counted in `triangles`, not drawn: the firmware
  // does not send them), e.g. texture coordinates beyond the record's range.
  uint64_t dropped = 0;
};

struct Frame {
  int width = 0, height = 0;
  std::vector<uint16_t> color;   // RGB565, row-major
  std::vector<uint32_t> depth;   // row-major
  std::vector<PixelProbe> probe; // row-major
  Counters counters;
};

}  // namespace htx
