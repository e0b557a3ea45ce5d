// Metrics of an engine's frame against the `ref` frame of the same scene (docs/metrics.md).
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "htx/model/image_io.hpp"
#include "htx/model/types.hpp"

namespace htx {

// Differences between two images of the same size over R, G, B (alpha ignored), in 8-bit units.
struct ImageDiff {
  double psnr_db = 0;           // +infinity when identical
  int max_channel_diff = 0;     // 0..255
  uint64_t differing_pixels = 0;
};
// Throws std::invalid_argument when the sizes differ.
ImageDiff compare_images(const Image& a, const Image& b);

// Bit-exactness of two frames of the same size (the RTL against the model): the pixels whose RGB565
// word or depth differ, and the first of them in row-major order as text, "(x, y): colour C depth D
// against colour C' depth D'". Throws std::invalid_argument when the sizes differ.
struct FrameMismatch {
  uint64_t pixels = 0;
  std::string first;  // empty when pixels == 0
};
FrameMismatch exact_mismatch(const Frame& a, const Frame& b);

// Labels copied into the JSON as they are.
struct MetricsLabels {
  std::string engine, scene, method, filter, config;
};

struct Metrics {
  MetricsLabels labels;
  int width = 0, height = 0;
  // Texel-coordinate error per pixel textured in both frames by the same scene mesh: max(|du|, |dv|)
  // between the engine's and ref's probe coordinates, in texels of ref's sampled mip level.
  double max_texel_error = 0, rms_texel_error = 0, p999_texel_error = 0;
  uint64_t compared_pixels = 0;
  double psnr_db = 0;  // +infinity when the frames are identical
  int max_channel_diff = 0;
  uint64_t coverage_diff_pixels = 0;  // textured in exactly one of the two frames
  uint64_t surface_diff_pixels = 0;   // textured in both, by different meshes (a moved edge or depth order)
  uint64_t divfree_max_steps = 0;
  double divfree_mean_steps = 0;
  uint64_t divfree_cap_hits = 0;
};

// Per-pixel texel-coordinate error, as defined for Metrics (engine probe against ref probe).
double texel_error(const PixelProbe& engine, const PixelProbe& ref);
// Whether a pixel's texel error counts (compute_metrics' compared_pixels): textured in both frames,
// by the same mesh (another mesh's coordinates are not an error of this one's interpolation).
inline bool compared_pixel(const PixelProbe& engine, const PixelProbe& ref) {
  return engine.covered && ref.covered && engine.mesh == ref.mesh;
}

// Throws std::invalid_argument when the frames' sizes differ or a frame is malformed.
Metrics compute_metrics(const Frame& engine, const Frame& ref, const MetricsLabels& labels);

// The JSON object with the documented keys; an infinite PSNR is written as null.
nlohmann::json metrics_to_json(const Metrics& m);

}  // namespace htx
