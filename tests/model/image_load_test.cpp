// load_image's limits and its guard for palette PNGs: the PNGs are built here byte by byte (a
// stored deflate block, so no compressor is needed), small enough to read in the test.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "htx/fw/crc32.h"
#include "htx/model/image_io.hpp"

namespace htx {
namespace {

void append_be32(std::string& s, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s.push_back(static_cast<char>(v >> shift));
}

void append_chunk(std::string& png, const std::string& type, const std::string& data) {
  append_be32(png, static_cast<uint32_t>(data.size()));
  const std::string body = type + data;
  png += body;
  append_be32(png, fw::crc32(reinterpret_cast<const uint8_t*>(body.data()), body.size()));
}

// An 8-bit palette PNG, `side` x `side`, every pixel index `index`, with `palette` RGB entries
// (entry i is grey level 10 * i).
std::string palette_png(int side, int palette, uint8_t index) {
  std::string png = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  append_be32(ihdr, static_cast<uint32_t>(side));
  append_be32(ihdr, static_cast<uint32_t>(side));
  ihdr += std::string{8, 3, 0, 0, 0};  // bit depth 8, colour type 3 (palette), no interlace
  append_chunk(png, "IHDR", ihdr);
  std::string plte;
  for (int i = 0; i < palette; ++i) plte += std::string(3, static_cast<char>(10 * i));
  append_chunk(png, "PLTE", plte);
  std::string raw;  // each scanline: filter type 0, then the indices
  for (int y = 0; y < side; ++y) raw += '\0' + std::string(static_cast<size_t>(side), static_cast<char>(index));
  // zlib: header, one stored block (final, LEN, NLEN), the Adler-32 of the raw bytes.
  std::string zlib = "\x78\x01";
  zlib += '\x01';
  const uint16_t len = static_cast<uint16_t>(raw.size());
  zlib += {static_cast<char>(len & 0xFF), static_cast<char>(len >> 8), static_cast<char>(~len & 0xFF),
           static_cast<char>((~len >> 8) & 0xFF)};
  zlib += raw;
  uint32_t a = 1, b = 0;
  for (char c : raw) {
    a = (a + static_cast<uint8_t>(c)) % 65521;
    b = (b + a) % 65521;
  }
  append_be32(zlib, b << 16 | a);
  append_chunk(png, "IDAT", zlib);
  append_chunk(png, "IEND", "");
  return png;
}

std::string write_temp(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() / ("htx_image_load_" + name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

TEST(ImageLoad, APaletteIndexWithinThePaletteLoadsItsColour) {
  const Image img = load_image(write_temp("in_palette.png", palette_png(8, 4, 3)));
  ASSERT_EQ(img.width, 8);
  ASSERT_EQ(img.height, 8);
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    ASSERT_EQ(img.rgba[i], 30);
    ASSERT_EQ(img.rgba[i + 3], 255);
  }
  // A full palette needs no guard and loads the same way.
  EXPECT_EQ(load_image(write_temp("full_palette.png", palette_png(8, 256, 200))).rgba[0], static_cast<uint8_t>(2000 & 0xFF));
}

// stb_image would expand index 200 of a 4-entry palette from uninitialised memory.
TEST(ImageLoad, APaletteIndexBeyondThePaletteIsACorruptImage) {
  const std::string path = write_temp("beyond_palette.png", palette_png(8, 4, 200));
  try {
    load_image(path);
    FAIL() << "loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("beyond its 4-entry palette"), std::string::npos) << e.what();
  }
}

// An image whose header claims more than kMaxImagePixels is refused before it is decoded.
TEST(ImageLoad, AnImageAboveThePixelLimitIsRefusedFromItsHeader) {
  std::string png = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  append_be32(ihdr, 10000);
  append_be32(ihdr, 10000);
  ihdr += std::string{8, 2, 0, 0, 0};  // 8-bit RGB
  append_chunk(png, "IHDR", ihdr);
  append_chunk(png, "IEND", "");
  try {
    load_image(write_temp("huge.png", png));
    FAIL() << "loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("10000x10000 is more than 67108864 pixels"), std::string::npos) << e.what();
  }
}

// A byte damaged anywhere in a chunk is refused by that chunk's CRC (stb_image checks neither the
// chunk CRCs nor zlib's checksum, so a flipped pixel byte loaded as a wrong texel); the undamaged
// file loads.
TEST(ImageLoad, AChunkWhoseCrcDoesNotMatchIsACorruptImage) {
  const std::string good = palette_png(8, 16, 5);
  ASSERT_EQ(load_image(write_temp("crc_good.png", good)).rgba.size(), 8u * 8u * 4u);
  const size_t idat = good.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  // A pixel index in the stored block (a valid index: it decodes, only to the wrong colour), a
  // byte of IHDR's width, and the IEND chunk's CRC.
  const struct {
    size_t at;
    std::string type;
  } cases[] = {{idat + 4 + 2 + 5 + 3, "IDAT"}, {8 + 8 + 3, "IHDR"}, {good.size() - 1, "IEND"}};
  for (const auto& c : cases) {
    std::string bad = good;
    bad[c.at] = static_cast<char>(bad[c.at] ^ 0x01);
    try {
      load_image(write_temp("crc_bad.png", bad));
      ADD_FAILURE() << "loaded with byte " << c.at << " damaged";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("the CRC of its " + c.type + " chunk at byte"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("(a corrupt PNG)"), std::string::npos) << e.what();
    }
  }
}

// A damaged ancillary chunk the decoder does not read (tEXt) is ignored, as libpng ignores it; one
// it reads (tRNS: transparency) is refused like a critical chunk.
TEST(ImageLoad, OnlyTheChunksTheDecoderReadsMustHaveTheirCrc) {
  const std::string good = palette_png(8, 16, 5);
  const size_t idat = good.find("IDAT") - 4;
  for (const std::string type : {"tEXt", "tRNS"}) {
    std::string chunk;
    append_chunk(chunk, type, type == "tEXt" ? std::string("Comment\0hello", 13) : std::string(16, '\xFF'));
    chunk[chunk.size() - 1] = static_cast<char>(chunk.back() ^ 0x40);  // the CRC's last byte
    const std::string png = good.substr(0, idat) + chunk + good.substr(idat);
    const std::string path = write_temp("ancillary.png", png);
    if (type == "tEXt") {
      EXPECT_EQ(load_image(path).rgba, load_image(write_temp("plain.png", good)).rgba);
    } else {
      try {
        load_image(path);
        ADD_FAILURE() << "loaded with a damaged " << type;
      } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("the CRC of its tRNS chunk"), std::string::npos) << e.what();
      }
    }
  }
}

// A PNG cut short anywhere before the end of its IEND chunk is refused, also where its pixel data
// is whole (stb_image decoded those).
TEST(ImageLoad, APngCutShortIsACorruptImage) {
  const std::string good = palette_png(8, 16, 5);
  for (size_t n = 8; n < good.size(); ++n) {
    try {
      load_image(write_temp("cut.png", good.substr(0, n)));
      ADD_FAILURE() << "loaded when cut to " << n << " of " << good.size() << " bytes";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("cut.png"), std::string::npos) << e.what();
    }
  }
}

TEST(ImageLoad, OnlyRegularFilesAreRead) {
  EXPECT_THROW(load_image("/dev/zero"), std::runtime_error);
  EXPECT_THROW(load_image(std::filesystem::temp_directory_path().string()), std::runtime_error);
  EXPECT_THROW(load_image("/nonexistent/x.png"), std::runtime_error);
}

}  // namespace
}  // namespace htx
