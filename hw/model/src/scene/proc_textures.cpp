#include "htx/model/proc_textures.hpp"


namespace htx {

std::vector<uint8_t> checkerboard_pixels(unsigned log2_width, unsigned log2_height, unsigned cell_log2,
                                         Rgba8 a, Rgba8 b) {
  const unsigned w = 1u << log2_width, h = 1u << log2_height;
  std::vector<uint8_t> px(static_cast<size_t>(w) * h * 4);
  for (unsigned y = 0; y < h; ++y)
    for (unsigned x = 0; x < w; ++x) {
      const Rgba8& c = (((x >> cell_log2) ^ (y >> cell_log2)) & 1) ? b : a;
      uint8_t* p = &px[(static_cast<size_t>(y) * w + x) * 4];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
      p[3] = c.a;
    }
  return px;
}

std::vector<uint8_t> gradient_pixels(unsigned log2_width, unsigned log2_height) {
  const unsigned w = 1u << log2_width, h = 1u << log2_height;
  std::vector<uint8_t> px(static_cast<size_t>(w) * h * 4);
  for (unsigned y = 0; y < h; ++y)
    for (unsigned x = 0; x < w; ++x) {
      uint8_t* p = &px[(static_cast<size_t>(y) * w + x) * 4];
      p[0] = static_cast<uint8_t>(x * 255 / (w - 1));
      p[1] = static_cast<uint8_t>(y * 255 / (h - 1));
      p[2] = static_cast<uint8_t>(((x + y) * 8) & 255);
      p[3] = 255;
    }
  return px;
}

Texture checkerboard_texture(TexFormat format, unsigned log2_size, unsigned cell_log2, Rgba8 a, Rgba8 b) {
  return make_texture(format, log2_size, log2_size,
                             checkerboard_pixels(log2_size, log2_size, cell_log2, a, b));
}

Texture gradient_texture(TexFormat format, unsigned log2_size) {
  return make_texture(format, log2_size, log2_size, gradient_pixels(log2_size, log2_size));
}

}  // namespace htx
