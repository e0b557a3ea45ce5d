#include "htx/sim/video_capture.hpp"

#include <cstddef>

namespace htx::sim {

VideoCapture::VideoCapture(uint32_t width, uint32_t height) : width_(width), height_(height) {
  current_.reserve(static_cast<std::size_t>(width) * height);
}

bool VideoCapture::clock(bool de, bool vsync_n, uint32_t rgb) {
  if (vsync_was_high_ && !vsync_n) {
    if (collecting_ && !current_.empty()) ++cut_frames_;
    current_.clear();
    collecting_ = true;
  }
  vsync_was_high_ = vsync_n;
  if (!collecting_ || !de) return false;
  current_.push_back(rgb);
  if (current_.size() == static_cast<std::size_t>(width_) * height_) {
    last_.swap(current_);
    current_.clear();
    collecting_ = false;
    ++frames_;
    return true;
  }
  return false;
}

std::vector<uint16_t> frame_from_screen(const std::vector<uint32_t>& picture, uint32_t width, uint32_t height,
                                        uint32_t scale) {
  std::vector<uint16_t> frame;
  if (scale == 0 || picture.size() != static_cast<std::size_t>(width) * height) return frame;
  for (uint32_t y = 0; y + scale <= height; y += scale) {
    for (uint32_t x = 0; x + scale <= width; x += scale) {
      const uint32_t p = picture[static_cast<std::size_t>(y) * width + x];
      for (uint32_t dy = 0; dy < scale; ++dy)
        for (uint32_t dx = 0; dx < scale; ++dx)
          if (picture[static_cast<std::size_t>(y + dy) * width + x + dx] != p) return {};
      frame.push_back(static_cast<uint16_t>(((p >> 19) << 11) | (((p >> 10) & 63) << 5) | ((p >> 3) & 31)));
    }
  }
  return frame;
}

}  // namespace htx::sim
