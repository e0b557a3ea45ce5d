// A monitor for the video scan-out's pins (htx_video, docs/video.md): fed one pixel clock at a
// time, it keeps the last whole frame shown. A frame starts at a vertical sync pulse's start and is
// whole when its width x height visible pixels (display enable high) have come; a frame cut short
// by the next sync pulse is dropped.
#pragma once

#include <cstdint>
#include <vector>

namespace htx::sim {

class VideoCapture {
 public:
  explicit VideoCapture(uint32_t width = 640, uint32_t height = 480);

  // One pixel clock: display enable, the vertical sync line (low = pulse) and the pixel (RGB888,
  // red in bits 23:16). True when this clock completed a whole frame (last_frame() is it).
  bool clock(bool de, bool vsync_n, uint32_t rgb);

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  uint64_t frames() const { return frames_; }          // whole frames seen
  uint64_t cut_frames() const { return cut_frames_; }  // frames dropped short
  // The last whole frame, row by row (empty before the first).
  const std::vector<uint32_t>& last_frame() const { return last_; }

 private:
  uint32_t width_, height_;
  bool vsync_was_high_ = true;
  bool collecting_ = false;
  std::vector<uint32_t> current_, last_;
  uint64_t frames_ = 0, cut_frames_ = 0;
};

// The framebuffer frame a screen picture shows: each scale x scale block of `picture` (RGB888,
// width x height, row by row) narrowed back to RGB565 (the scan-out widens by repeating the top
// bits, so nothing is lost), (width / scale) x (height / scale) pixels; empty when a block is not
// one colour, which no whole frame of the framebuffer shows.
std::vector<uint16_t> frame_from_screen(const std::vector<uint32_t>& picture, uint32_t width, uint32_t height,
                                        uint32_t scale);

}  // namespace htx::sim
