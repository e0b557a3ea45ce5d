#include "htx/sim/video_capture.hpp"

#include <cstddef>

namespace htx::sim {

VideoCapture::VideoCapture(uint32_t width, uint32_t height) : width_(width), height_(height) {
  current_.reserve(static_cast<std::size_t>(width) * height);
}

void VideoCapture::clock(bool de, bool vsync_n, uint32_t rgb) {
  if (vsync_was_high_ && !vsync_n) {
    if (collecting_ && !current_.empty()) ++cut_frames_;
    current_.clear();
    collecting_ = true;
  }
  vsync_was_high_ = vsync_n;
  if (!collecting_ || !de) return;
  current_.push_back(rgb);
  if (current_.size() == static_cast<std::size_t>(width_) * height_) {
    last_.swap(current_);
    current_.clear();
    collecting_ = false;
    ++frames_;
  }
}

}  // namespace htx::sim
