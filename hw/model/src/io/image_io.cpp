#include "htx/model/image_io.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "htx/fw/crc32.h"
#include "htx/host/file_in.hpp"
#include "htx/model/file_out.hpp"

namespace htx {

namespace {

std::string read_image_file(const std::string& path) {
  try {
    return host::read_regular_file(path, kMaxImageFileBytes);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("cannot load image '" + path + "': " + e.what());
  }
}

uint32_t be32(const std::string& s, size_t at) {
  return static_cast<uint32_t>(static_cast<uint8_t>(s[at])) << 24 | static_cast<uint32_t>(static_cast<uint8_t>(s[at + 1])) << 16 |
         static_cast<uint32_t>(static_cast<uint8_t>(s[at + 2])) << 8 | static_cast<uint8_t>(s[at + 3]);
}

void append_be32(std::string& s, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s.push_back(static_cast<char>(v >> shift));
}

const std::string kPngSignature = "\x89PNG\r\n\x1a\n";

bool is_png(const std::string& bytes) { return bytes.compare(0, kPngSignature.size(), kPngSignature) == 0; }

// Calls visit(at, length, type) for each whole chunk of a PNG in order (at: where its length field
// is) until visit returns false. Returns npos when visit stopped the walk, else where the chunk
// that runs past the file's end begins (the file's end when none is left).
template <class Visit>
size_t walk_png_chunks(const std::string& png, Visit visit) {
  for (size_t at = kPngSignature.size();;) {
    if (at + 12 > png.size()) return at;
    const uint32_t length = be32(png, at);
    if (length > png.size() - at - 12) return at;
    if (!visit(at, length, std::string_view(png.data() + at + 4, 4))) return std::string::npos;
    at += 12 + length;
  }
}

// A palette PNG's PLTE chunk: where it starts and how many entries it has (0 entries: not a
// palette PNG, or a structure the decoder will refuse itself).
struct PaletteChunk {
  size_t at = 0;
  uint32_t entries = 0;
};

PaletteChunk find_palette(const std::string& png) {
  constexpr size_t kColourTypeAt = 8 + 8 + 9;  // IHDR's data: width, height, bit depth, colour type
  if (!is_png(png) || png.size() <= kColourTypeAt || png[kColourTypeAt] != 3) return {};
  PaletteChunk plte;
  walk_png_chunks(png, [&](size_t at, uint32_t length, std::string_view type) {
    if (type != "PLTE") return true;
    if (length % 3 == 0) plte = {at, length / 3};
    return false;
  });
  return plte;
}

// The PNG with its palette padded to 256 entries of one grey level (the chunk's CRC made anew).
std::string with_padded_palette(const std::string& png, const PaletteChunk& plte, uint8_t grey) {
  const size_t data_at = plte.at + 8, data_len = size_t{plte.entries} * 3;
  std::string chunk = "PLTE" + png.substr(data_at, data_len) + std::string(768 - data_len, static_cast<char>(grey));
  std::string out = png.substr(0, plte.at);
  append_be32(out, 768);
  out += chunk;
  append_be32(out, fw::crc32(reinterpret_cast<const uint8_t*>(chunk.data()), chunk.size()));
  out += png.substr(data_at + data_len + 4);
  return out;
}

// A PNG's chunks each end with the CRC-32 of their type and data, which stb_image does not check
// (nor zlib's own checksum): a damaged byte decoded silently into a wrong texel. Each chunk the
// decoder reads, up to IEND, is checked here, and a file that ends before IEND (a chunk running
// past its end, or none left) is refused too: stb_image decoded such a file when its pixel data
// came before the damage.
void check_png_chunks(const std::string& png, const std::string& path) {
  if (!is_png(png)) return;
  const size_t end = walk_png_chunks(png, [&](size_t at, uint32_t length, std::string_view type) {
    // The chunks the decoder reads: the critical ones (an upper-case first letter), tRNS
    // (transparency) and CgBI. Other ancillary chunks are ignored, damaged or not, as libpng
    // drops them with a warning.
    const bool read = !(type[0] & 0x20) || type == "tRNS" || type == "CgBI";
    const uint32_t crc = fw::crc32(reinterpret_cast<const uint8_t*>(png.data() + at + 4), size_t{length} + 4);
    if (read && crc != be32(png, at + 8 + length)) {
      std::string shown(type);
      for (char& c : shown)
        if (c < 0x20 || c > 0x7E) c = '?';
      throw std::runtime_error("cannot load image '" + path + "': the CRC of its " + shown + " chunk at byte " +
                               std::to_string(at) + " does not match (a corrupt PNG)");
    }
    return type != "IEND";
  });
  if (end != std::string::npos)
    throw std::runtime_error("cannot load image '" + path + "': it ends before its IEND chunk, in the chunk at byte " +
                             std::to_string(end) + " (a truncated or corrupt PNG)");
}

std::vector<uint8_t> decode(const std::string& bytes, const std::string& path, int* w, int* h) {
  int channels = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                              static_cast<int>(bytes.size()), w, h, &channels, 4);
  if (!data) {
    const char* reason = stbi_failure_reason();
    throw std::runtime_error("cannot load image '" + path + "': " + (reason ? reason : "unknown error"));
  }
  std::vector<uint8_t> rgba(data, data + static_cast<size_t>(*w) * static_cast<size_t>(*h) * 4);
  stbi_image_free(data);
  return rgba;
}

}  // namespace

Image load_image(const std::string& path) {
  const std::string bytes = read_image_file(path);
  check_png_chunks(bytes, path);
  int w = 0, h = 0, channels = 0;
  if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &w, &h,
                            &channels) &&
      static_cast<uint64_t>(w) * static_cast<uint64_t>(h) > kMaxImagePixels)
    throw std::runtime_error("cannot load image '" + path + "': " + std::to_string(w) + "x" + std::to_string(h) +
                             " is more than " + std::to_string(kMaxImagePixels) + " pixels");
  Image img;
  // stb_image expands a palette through a 256-entry table that it leaves uninitialised past the
  // file's own entries. A palette shorter than 256 is padded in two grey levels and the image
  // decoded twice: if the two differ, a pixel's index is beyond the palette.
  const PaletteChunk plte = find_palette(bytes);
  if (plte.entries > 0 && plte.entries < 256) {
    img.rgba = decode(with_padded_palette(bytes, plte, 0x00), path, &img.width, &img.height);
    if (decode(with_padded_palette(bytes, plte, 0xFF), path, &w, &h) != img.rgba)
      throw std::runtime_error("cannot load image '" + path + "': a pixel's palette index is beyond its " +
                               std::to_string(plte.entries) + "-entry palette (a corrupt PNG)");
  } else {
    img.rgba = decode(bytes, path, &img.width, &img.height);
  }
  return img;
}

void write_png(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
    throw std::runtime_error("cannot write '" + path + "': malformed image");
  // Encoded in memory, then written checked: stbi_write_png does not report a failed write.
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw std::runtime_error("cannot write PNG '" + path + "': the encoder failed");
  write_file(path, png);
}

uint32_t rgb888_from_rgb565(uint16_t pixel) {
  const uint32_t r = pixel >> 11 & 31, g = pixel >> 5 & 63, b = pixel & 31;
  return (r << 3 | r >> 2) << 16 | (g << 2 | g >> 4) << 8 | (b << 3 | b >> 2);
}

Image image_from_rgb888(int width, int height, const std::vector<uint32_t>& pixels) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(pixels.size() * 4);
  for (size_t i = 0; i < pixels.size(); ++i) {
    img.rgba[i * 4 + 0] = static_cast<uint8_t>(pixels[i] >> 16);
    img.rgba[i * 4 + 1] = static_cast<uint8_t>(pixels[i] >> 8);
    img.rgba[i * 4 + 2] = static_cast<uint8_t>(pixels[i]);
    img.rgba[i * 4 + 3] = 255;
  }
  return img;
}

Image image_from_rgb565(int width, int height, const std::vector<uint16_t>& pixels) {
  std::vector<uint32_t> rgb(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) rgb[i] = rgb888_from_rgb565(pixels[i]);
  return image_from_rgb888(width, height, rgb);
}

namespace {

// For each of `to` cells over `from` source pixels (to <= from): the first source pixel it touches
// and the weights of the pixels it covers, in units of 1/from of a cell's width times `to`
// (cell c covers [c * from, (c + 1) * from) in units of 1/to of a source pixel).
struct Coverage {
  int first = 0;
  std::vector<int> weights;  // summing to `from`
};
std::vector<Coverage> coverage(int from, int to) {
  std::vector<Coverage> cells(static_cast<size_t>(to));
  for (int c = 0; c < to; ++c) {
    const long lo = static_cast<long>(c) * from, hi = static_cast<long>(c + 1) * from;  // in 1/to pixels
    Coverage& cov = cells[static_cast<size_t>(c)];
    cov.first = static_cast<int>(lo / to);
    for (long p = lo / to; p * to < hi; ++p) {
      const long a = std::max(lo, p * to), b = std::min(hi, (p + 1) * to);
      cov.weights.push_back(static_cast<int>(b - a));
    }
  }
  return cells;
}

}  // namespace

Image shrink_image(const Image& image, int width, int height) {
  if (width < 1 || height < 1 || width > image.width || height > image.height ||
      image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
    throw std::invalid_argument("shrink_image: the new size must be within the image's");
  const std::vector<Coverage> cx = coverage(image.width, width), cy = coverage(image.height, height);
  Image out;
  out.width = width;
  out.height = height;
  out.rgba.resize(static_cast<size_t>(width) * height * 4);
  // Each weight is in units of 1/(to) source pixels per axis; a pixel's weights sum to
  // image.width * image.height, so the mean is the weighted sum over that, rounded.
  const uint64_t total = static_cast<uint64_t>(image.width) * image.height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 4; ++c) {
        uint64_t sum = 0;
        const Coverage& vy = cy[static_cast<size_t>(y)];
        const Coverage& vx = cx[static_cast<size_t>(x)];
        for (size_t j = 0; j < vy.weights.size(); ++j)
          for (size_t i = 0; i < vx.weights.size(); ++i) {
            const size_t px =
                (static_cast<size_t>(vy.first + static_cast<int>(j)) * image.width + vx.first + static_cast<int>(i)) *
                    4 +
                static_cast<size_t>(c);
            sum += static_cast<uint64_t>(vy.weights[j]) * static_cast<uint64_t>(vx.weights[i]) * image.rgba[px];
          }
        out.rgba[(static_cast<size_t>(y) * width + x) * 4 + static_cast<size_t>(c)] =
            static_cast<uint8_t>((sum + total / 2) / total);
      }
  return out;
}

Image halve_image(const Image& image) {
  if (image.width < 2 || image.height < 2 || image.width % 2 || image.height % 2 ||
      image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
    throw std::invalid_argument("halve_image: sides must be even and at least 2");
  Image half;
  half.width = image.width / 2;
  half.height = image.height / 2;
  half.rgba.resize(static_cast<size_t>(half.width) * half.height * 4);
  const size_t stride = static_cast<size_t>(image.width) * 4;
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x)
      for (int c = 0; c < 4; ++c) {
        const size_t i = 2 * static_cast<size_t>(y) * stride + 8 * static_cast<size_t>(x) + static_cast<size_t>(c);
        const unsigned sum = image.rgba[i] + image.rgba[i + 4] + image.rgba[i + stride] + image.rgba[i + stride + 4];
        half.rgba[(static_cast<size_t>(y) * half.width + x) * 4 + c] = static_cast<uint8_t>((sum + 2) >> 2);
      }
  return half;
}

}  // namespace htx
