// Test support: the frame a render through the HAL left in the (simulated) GPU, read back through
// the HAL's framebuffer driver as firmware reads it: colour, and depth masked to the configuration's
// z_bits (none when z_bits is 0). Shared by the cosim tests and the system render test.
#pragma once

#include <cstddef>
#include <cstdint>

#include "htx/hal/framebuffer.h"
#include "htx/model/types.hpp"

namespace htx::test {

inline Frame read_frame_through_hal(int width, int height, unsigned z_bits) {
  Frame f;
  f.width = width;
  f.height = height;
  const uint32_t w = static_cast<uint32_t>(width);
  f.color.resize(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    hal::fb_read_row(w, static_cast<uint32_t>(y), 0, w, &f.color[static_cast<size_t>(y) * w]);
  if (z_bits == 0) return f;
  const uint32_t z_max = z_bits >= 32 ? ~uint32_t{0} : (uint32_t{1} << z_bits) - 1;
  f.depth.reserve(f.color.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      f.depth.push_back(hal::fb_read_depth(w, static_cast<uint32_t>(x), static_cast<uint32_t>(y)) & z_max);
  return f;
}

}  // namespace htx::test
