#include "htx/model/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace htx {

namespace {

void check_frame(const Frame& f, const char* what) {
  const size_t n = static_cast<size_t>(std::max(f.width, 0)) * static_cast<size_t>(std::max(f.height, 0));
  if (f.color.size() != n || f.probe.size() != n)
    throw std::invalid_argument(std::string("malformed ") + what + " frame");
}

}  // namespace

double texel_error(const PixelProbe& engine, const PixelProbe& ref) {
  const double scale = std::ldexp(1.0, -ref.level);
  return std::max(std::fabs(engine.u - ref.u), std::fabs(engine.v - ref.v)) * scale;
}

Metrics compute_metrics(const Frame& engine, const Frame& ref, const MetricsLabels& labels) {
  check_frame(engine, "engine");
  check_frame(ref, "ref");
  if (engine.width != ref.width || engine.height != ref.height)
    throw std::invalid_argument("engine and ref frames differ in size");
  Metrics m;
  m.labels = labels;
  m.width = ref.width;
  m.height = ref.height;

  std::vector<double> errors;
  double sum_sq = 0;
  for (size_t i = 0; i < ref.probe.size(); ++i) {
    const PixelProbe& e = engine.probe[i];
    const PixelProbe& r = ref.probe[i];
    if (e.covered != r.covered) ++m.coverage_diff_pixels;
    if (!compared_pixel(e, r)) {
      if (e.covered && r.covered) ++m.surface_diff_pixels;  // another mesh in each frame
      continue;
    }
    const double err = texel_error(e, r);
    errors.push_back(err);
    sum_sq += err * err;
  }
  m.compared_pixels = errors.size();
  if (!errors.empty()) {
    std::sort(errors.begin(), errors.end());
    m.max_texel_error = errors.back();
    m.rms_texel_error = std::sqrt(sum_sq / static_cast<double>(errors.size()));
    // Nearest-rank percentile: the smallest error at or above which lie at most 0.1 % of the pixels.
    const size_t rank = static_cast<size_t>(std::ceil(0.999 * static_cast<double>(errors.size())));
    m.p999_texel_error = errors[std::max<size_t>(rank, 1) - 1];
  }

  const ImageDiff d = compare_images(image_from_rgb565(engine.width, engine.height, engine.color),
                                     image_from_rgb565(ref.width, ref.height, ref.color));
  m.psnr_db = d.psnr_db;
  m.max_channel_diff = d.max_channel_diff;

  const Counters& c = engine.counters;
  m.divfree_max_steps = c.divfree_steps_max;
  m.divfree_mean_steps =
      c.divfree_pixels ? static_cast<double>(c.divfree_steps_total) / static_cast<double>(c.divfree_pixels) : 0;
  m.divfree_cap_hits = c.divfree_cap_hits;
  return m;
}

nlohmann::json metrics_to_json(const Metrics& m) {
  nlohmann::json j;
  j["engine"] = m.labels.engine;
  j["scene"] = m.labels.scene;
  j["method"] = m.labels.method;
  j["filter"] = m.labels.filter;
  j["config"] = m.labels.config;
  j["width"] = m.width;
  j["height"] = m.height;
  j["max_texel_error"] = m.max_texel_error;
  j["rms_texel_error"] = m.rms_texel_error;
  j["p999_texel_error"] = m.p999_texel_error;
  j["compared_pixels"] = m.compared_pixels;
  if (std::isfinite(m.psnr_db))
    j["psnr_db"] = m.psnr_db;
  else
    j["psnr_db"] = nullptr;
  j["max_channel_diff"] = m.max_channel_diff;
  j["coverage_diff_pixels"] = m.coverage_diff_pixels;
  j["surface_diff_pixels"] = m.surface_diff_pixels;
  j["divfree_max_steps"] = m.divfree_max_steps;
  j["divfree_mean_steps"] = m.divfree_mean_steps;
  j["divfree_cap_hits"] = m.divfree_cap_hits;
  return j;
}

}  // namespace htx
