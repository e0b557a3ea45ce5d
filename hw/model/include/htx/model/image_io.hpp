// Images on disk: PNG in and out (stb_image / stb_image_write), and RGB565 frames as 8-bit images.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace htx {

// 8-bit RGBA, row-major, top row first.
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

// The largest image load_image decodes: 8192 x 8192 pixels (a texture is drawn from a mip level
// of at most 256 x 256 anyway), from a regular file of at most 256 MiB.
inline constexpr uint64_t kMaxImagePixels = uint64_t{1} << 26;
inline constexpr uint64_t kMaxImageFileBytes = uint64_t{256} << 20;

// Loads any image stb_image reads (PNG and others) as RGBA8. Throws std::runtime_error with the
// file name and the reason on failure: the decoder's, a file or an image above the limits, or a
// palette PNG with a pixel whose index is beyond its palette (corrupt: stb_image would read
// uninitialised memory for it).
Image load_image(const std::string& path);

// Writes a PNG. Throws std::runtime_error on failure.
void write_png(const std::string& path, const Image& image);

// One RGB565 pixel widened to RGB888 by bit replication (0x1F -> 0xFF): red in bits 23:16, green
// 15:8, blue 7:0, as the video scan-out's pins carry it (docs/video.md).
uint32_t rgb888_from_rgb565(uint16_t pixel);

// Pixels of RGB888 (red in bits 23:16) as an image, alpha 255.
Image image_from_rgb888(int width, int height, const std::vector<uint32_t>& pixels);

// Expands RGB565 to RGB8 by bit replication (0x1F -> 0xFF), alpha 255.
Image image_from_rgb565(int width, int height, const std::vector<uint16_t>& pixels);

// The image shrunk to width x height (each at most the image's, at least 1) by area averaging: a
// new pixel is the mean of the source area it covers, partly covered pixels weighted by their
// share, each channel rounded to nearest. std::invalid_argument for a size it cannot make.
Image shrink_image(const Image& image, int width, int height);

// The image at half its width and height by a 2x2 box filter, (a + b + c + d + 2) >> 2 per
// channel, as the texture unit's mip levels are made. Needs even sides (std::invalid_argument).
Image halve_image(const Image& image);

}  // namespace htx
