#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "htx/model/metrics.hpp"

namespace htx {

ImageDiff compare_images(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("image sizes differ: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height));
  const size_t n = static_cast<size_t>(a.width) * a.height;
  if (a.rgba.size() != n * 4 || b.rgba.size() != n * 4) throw std::invalid_argument("malformed image");
  ImageDiff d;
  double sq = 0;
  for (size_t i = 0; i < n; ++i) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      const int diff = std::abs(int{a.rgba[i * 4 + c]} - int{b.rgba[i * 4 + c]});
      sq += static_cast<double>(diff) * diff;
      d.max_channel_diff = std::max(d.max_channel_diff, diff);
      differs |= diff != 0;
    }
    d.differing_pixels += differs;
  }
  const double mse = n ? sq / (3.0 * n) : 0;
  d.psnr_db = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  return d;
}

FrameMismatch exact_mismatch(const Frame& a, const Frame& b) {
  const size_t n = static_cast<size_t>(a.width) * a.height;
  if (a.width != b.width || a.height != b.height || a.color.size() != n || b.color.size() != n ||
      a.depth.size() != n || b.depth.size() != n)
    throw std::invalid_argument("exact_mismatch: the frames' sizes differ");
  FrameMismatch m;
  for (size_t i = 0; i < n; ++i) {
    if (a.color[i] == b.color[i] && a.depth[i] == b.depth[i]) continue;
    if (m.pixels++ == 0) {
      m.first = "(" + std::to_string(i % a.width) + ", " + std::to_string(i / a.width) + "): colour " +
                std::to_string(a.color[i]) + " depth " + std::to_string(a.depth[i]) + " against colour " +
                std::to_string(b.color[i]) + " depth " + std::to_string(b.depth[i]);
    }
  }
  return m;
}

}  // namespace htx
