// OBJ/PNG loading, PNG writing, metrics and their JSON, names and scene specs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "htx/model/geometry.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/metrics.hpp"
#include "htx/model/names.hpp"
#include "htx/model/obj_loader.hpp"
#include "htx/model/ref.hpp"
#include "htx/model/scenes.hpp"
#include "htx/model/texture.hpp"

namespace htx {
namespace {

const std::string kData = HTX_MODEL_TEST_DATA;

TEST(RefIo, LoadsObjWithMaterialsAndPngTexture) {
  const Scene s = load_obj_scene(kData + "/quad.obj");
  ASSERT_EQ(s.textures.size(), 1u);
  const Texture& tex = s.textures[0];
  EXPECT_EQ(tex.log2_width, 3u);
  EXPECT_EQ(tex.log2_height, 4u);
  // v = 0 is the image's bottom row (blue), the top image row (red) is texel row 15.
  EXPECT_EQ(fetch_texel(tex, 0, 0, 0), (Rgba8{0, 0, 255, 255}));
  EXPECT_EQ(fetch_texel(tex, 0, 5, 15), (Rgba8{255, 0, 0, 255}));
  ASSERT_EQ(s.meshes.size(), 2u);
  const Mesh* quad = nullptr;
  const Mesh* tri = nullptr;
  for (const Mesh& m : s.meshes) (m.name == "quad" ? quad : tri) = &m;
  ASSERT_TRUE(quad && tri);
  EXPECT_TRUE(quad->state.textured);
  EXPECT_EQ(quad->triangles.size(), 2u);
  EXPECT_DOUBLE_EQ(quad->vertices[quad->triangles[0][1]].s, 1);
  EXPECT_DOUBLE_EQ(quad->vertices[quad->triangles[0][1]].pos.x, 1);
  EXPECT_FALSE(tri->state.textured);
  EXPECT_DOUBLE_EQ(tri->vertices[0].r, 1);
  EXPECT_DOUBLE_EQ(tri->vertices[0].g, 0);
  // The automatic camera frames it: both meshes draw.
  const ScreenScene screen = prepare_screen_scene(s, 64, 64);
  EXPECT_EQ(screen.tris.size(), 3u);
  const Frame f = render_ref(screen, {});
  EXPECT_GT(f.counters.pixels_written, 500u);
}

TEST(RefIo, ObjErrorsAreClear) {
  EXPECT_THROW(load_obj_scene(kData + "/missing.obj"), std::runtime_error);
  const auto dir = std::filesystem::temp_directory_path() / "htx_ref_io_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.mtl") << "newmtl m\nmap_Kd odd.png\n";
  Image odd;  // 12 x 4: its power-of-two form, 8 x 4, is too small
  odd.width = 12;
  odd.height = 4;
  odd.rgba.assign(12 * 4 * 4, 128);
  write_png((dir / "odd.png").string(), odd);
  std::ofstream(dir / "bad.obj") << "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n";
  try {
    load_obj_scene((dir / "bad.obj").string());
    FAIL() << "a 12 x 4 texture must be rejected";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is 12x4; no mip level of it (or of its power-of-two form) has both sides"),
              std::string::npos)
        << e.what();
  }
  // A non-finite vertex in any mesh (here the second one) is rejected, not only in the first.
  for (const char* f : {"quad.mtl", "checker8x16.png"})
    std::filesystem::copy_file(kData + "/" + f, dir / f, std::filesystem::copy_options::overwrite_existing);
  {
    std::ifstream in(kData + "/quad.obj");
    std::ofstream out(dir / "inf.obj");
    std::string line;
    while (std::getline(in, line)) out << (line == "v 0 0 -1" ? "v 1e308 0 -1" : line) << "\n";
  }
  try {
    load_obj_scene((dir / "inf.obj").string());
    FAIL() << "a vertex at 1e308 (infinite as float) must be rejected";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 7: '1e308' is not a finite decimal number as a float"), std::string::npos)
        << e.what();
  }
  // What tinyobjloader reads as 0 without a word, or only warns of, and would draw other than
  // written: each file is refused, naming the line where there is one.
  std::ofstream(dir / "grey.mtl") << "newmtl grey\nKd 0.5\n";
  std::ofstream(dir / "nan.mtl") << "newmtl m\nKd 1 nan 1\n";
  const auto with_line = [](const char* line) { return std::string("v 0 0 0\n") + line + "\nv 0 1 0\nvt 0 0\nf 1 2 3\n"; };
  const struct {
    std::string text;
    const char* message;
  } refused[] = {
      {with_line("v nan 1 0"), "line 2: 'nan' is not a finite decimal"},
      {with_line("v 1 abc 0"), "line 2: 'abc' is not a finite decimal"},
      {with_line("v 0x1p3 1 0"), "line 2: '0x1p3' is not a finite decimal"},
      {with_line("v 1e999 1 0"), "line 2: '1e999' is not a finite decimal"},
      {with_line("v 1. 2e 0"), "line 2: '2e' is not a finite decimal"},
      {with_line("v 1 2"), "line 2: 'v' with 2 numbers"},
      {with_line("vt 0.5 inf"), "line 2: 'inf' is not a finite decimal"},
      {with_line("vt"), "line 2: 'vt' with 0 numbers"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n", "line 5: texture coordinate index 2 out of range"},
      {"mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: material library 'none.mtl' not found"},
      {"mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl blue\nf 1 2 3\n", "usemtl 'blue' is in none"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n", "usemtl 'red' is in none"},
      {"mtllib grey.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "grey.mtl' line 2: 'Kd' with 1 numbers"},
      {"mtllib nan.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "nan.mtl' line 2: 'nan' is not a finite decimal"},
  };
  for (const auto& c : refused) {
    std::ofstream(dir / "refused.obj") << c.text;
    try {
      load_obj_scene((dir / "refused.obj").string());
      ADD_FAILURE() << c.text << " must be refused";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    }
  }
  // What OBJ files do write is taken: signs, a point at either end, exponents, w, colours, comments.
  std::ofstream(dir / "forms.obj") << "v +1. -.5 0e0 1\nv 1.5E+2 0 -1e-3 1 0.5 0\n  v 0 1 0 # a comment\r\n"
                                   << "vt .25\nvt 0 1 0\nf 1/1 2/2 3/2\n";
  const Scene forms = load_obj_scene((dir / "forms.obj").string());
  ASSERT_EQ(forms.meshes.size(), 1u);
  EXPECT_EQ(forms.meshes[0].vertices[1].pos.x, 150.0);
  EXPECT_EQ(forms.meshes[0].vertices[0].s, 0.25);
  std::filesystem::remove_all(dir);
}

// Loads `text` as dir/name and returns the error, or "" when it loads.
std::string obj_error(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name, std::ios::binary) << text;
  try {
    load_obj_scene((dir / name).string());
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// A UTF-8 byte-order mark first in an OBJ or an MTL (Windows editors write one) is stripped:
// tinyobjloader read "\xEF\xBB\xBFv" as an unknown keyword, so the first vertex vanished and
// every index after it pointed one vertex on; an MTL's first material vanished (drawn white).
TEST(RefIo, ByteOrderMarksBeforeAnObjOrMtlAreStripped) {
  const auto dir = std::filesystem::temp_directory_path() / "htx_ref_io_bom";
  std::filesystem::create_directories(dir);
  const std::string bom = "\xEF\xBB\xBF";
  std::ofstream(dir / "red.mtl", std::ios::binary) << bom << "newmtl red\nKd 1 0 0\n";
  ASSERT_EQ(obj_error(dir, "bom.obj", bom + "v 5 5 5\nv 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib red.mtl\nusemtl red\nf 2 3 4\n"),
            "");
  const Scene s = load_obj_scene((dir / "bom.obj").string());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.triangles.size(), 1u);
  const Vec3 want[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (size_t k = 0; k < 3; ++k) {
    const Vertex& v = m.vertices[m.triangles[0][k]];
    EXPECT_EQ(v.pos.x, want[k].x) << k;
    EXPECT_EQ(v.pos.y, want[k].y) << k;
    EXPECT_EQ(v.pos.z, want[k].z) << k;
    EXPECT_EQ(v.r, 1.0) << k;
    EXPECT_EQ(v.g, 0.0) << k;
  }
  std::filesystem::remove_all(dir);
}

// An OBJ or MTL larger than kMaxSceneFileBytes is refused before it is read (a 3 GB one ran out of
// memory), and one holding a NUL byte is not text (an error quoting a word was cut at the NUL).
TEST(RefIo, ObjFilesTooLargeOrNotTextAreRefused) {
  const auto dir = std::filesystem::temp_directory_path() / "htx_ref_io_limits";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "huge.obj") << "v 0 0 0\n";
  std::filesystem::resize_file(dir / "huge.obj", kMaxSceneFileBytes + 1);  // sparse: nothing is written
  EXPECT_EQ(obj_error(dir, "ok.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "");
  const std::string huge_path = (dir / "huge.obj").string();
  try {
    load_obj_scene(huge_path);
    ADD_FAILURE() << "loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read '" + huge_path + "': " + std::to_string(kMaxSceneFileBytes + 1) +
                                         " bytes, more than the " + std::to_string(kMaxSceneFileBytes) + " read");
  }
  EXPECT_EQ(obj_error(dir, "nul.obj", std::string("v 0 0 0\nv 1\0 0 0\nv 0 1 0\nf 1 2 3\n", 33)),
            "'" + (dir / "nul.obj").string() + "' line 2: a NUL byte (not a text file)");
  std::ofstream(dir / "nul.mtl", std::ios::binary) << std::string("newmtl a\nKd 1 1\0 1\n", 19);
  EXPECT_EQ(obj_error(dir, "lib.obj", "mtllib nul.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n"),
            "'" + (dir / "nul.mtl").string() + "' line 2: a NUL byte (not a text file)");
  std::filesystem::remove_all(dir);
}

// What tinyobjloader dropped with only a warning (a face) or drew otherwise than written (a
// material not yet read, a texture coordinate of a relative index before the first `vt`, one at
// some corners only, a number finite as a double but not as its float) is refused, by its line.
TEST(RefIo, FacesTinyobjloaderWouldDropOrMisreadAreRefused) {
  const auto dir = std::filesystem::temp_directory_path() / "htx_ref_io_faces";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "m.mtl") << "newmtl m\nKd 1 0 0\n";
  std::ofstream(dir / "n.mtl") << "newmtl n\nKd 0 1 0\n";
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::string tex = three + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
  const struct {
    std::string text;
    const char* message;
  } refused[] = {
      {three + "f 1 2 3 4\n", "line 4: vertex index 4 out of range (the file has 3 v lines)"},
      {three + "f 1 2 3\nf 1 2\n", "line 5: a face with 2 corners (a face has 3 or more)"},
      {three + "f 1\n", "line 4: a face with 1 corners"},
      {three + "f 1 2 -4\n", "line 4: vertex index -4 out of range (3 v lines before it)"},
      {three + "f 1 2 3.5\n", "line 4: '3.5' is not a vertex index"},
      {three + "f 1 2/ 3\n", "line 4: '2/' is not a face corner"},
      {tex + "f 1/1 2/-9 3/3\n", "line 8: texture coordinate index -9 out of range (3 vt lines before it)"},
      {tex + "f 1/1 2/9 3/3\n", "line 8: texture coordinate index 9 out of range (the file has 3 vt lines)"},
      {tex + "f 1/1/1 2/2/-2 3/3/1\n", "line 8: normal index -2 out of range (1 vn line before it)"},
      {tex + "f 1//1 2//2 3//1\n", "line 8: normal index 2 out of range (the file has 1 vn line)"},
      {tex + "f 1/1 2 3/1\n", "line 8: a face with texture coordinates at 2 of its 3 corners"},
      {three + "vt 1e39 0\nf 1/1 2/1 3/1\n", "line 4: '1e39' is not a finite decimal number as a float"},
      {"v 0 0 0 1 -1e39 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: '-1e39' is not a finite decimal number as a float"},
      {three + "usemtl m\nmtllib m.mtl\nf 1 2 3\n", "line 4: usemtl 'm' is in none of the material libraries before it"},
      // tinyobjloader reads only the first library of an mtllib line: its warning is an error.
      {"mtllib m.mtl n.mtl\n" + three + "usemtl n\nf 1 2 3\n", "material [ 'n' ] not found in .mtl"},
  };
  for (const auto& c : refused)
    EXPECT_NE(obj_error(dir, "refused.obj", c.text).find(c.message), std::string::npos)
        << c.text << "gave: " << obj_error(dir, "refused.obj", c.text);
  // Relative indices within range, and a material from a library before its usemtl, are taken.
  EXPECT_EQ(obj_error(dir, "good.obj", "mtllib m.mtl\n" + tex + "usemtl m\nf -3/-3/-1 -2/-2/-1 -1/-1/-1\n"), "");
  std::filesystem::remove_all(dir);
}

// map_Kd's options: -clamp on clamps that material's texture (it repeats otherwise); -s, -o and -t,
// which move the image on the surface, are refused by material (they were dropped silently); a
// map_Kd image that is not there is named with the material; CR alone ends a line (classic Mac OS).
TEST(RefIo, MapKdOptionsAreDrawnOrRefusedAndCrEndsALine) {
  const auto dir = std::filesystem::temp_directory_path() / "htx_ref_io_map_kd";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kData + "/checker8x16.png", dir / "checker8x16.png",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "m.mtl") << "newmtl clamped\nmap_Kd -clamp on checker8x16.png\n"
                                  "newmtl plain\nmap_Kd checker8x16.png\n"
                                  "newmtl scaled\nmap_Kd -s 2 2 1 checker8x16.png\n"
                                  "newmtl moved\nmap_Kd -o 0.5 0 0 checker8x16.png\n"
                                  "newmtl missing\nmap_Kd nothere.png\n";
  const std::string tri = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
  ASSERT_EQ(obj_error(dir, "c.obj", tri + "usemtl clamped\nf 1/1 2/1 3/1\nusemtl plain\nf 3/1 2/1 1/1\n"), "");
  const Scene s = load_obj_scene((dir / "c.obj").string());
  ASSERT_EQ(s.meshes.size(), 2u);
  int clamped = 0;
  for (const Mesh& m : s.meshes) {
    const bool clamp = m.state.wrap_u == Wrap::Clamp && m.state.wrap_v == Wrap::Clamp;
    const bool repeat = m.state.wrap_u == Wrap::Repeat && m.state.wrap_v == Wrap::Repeat;
    EXPECT_TRUE(clamp || repeat);
    clamped += clamp;
  }
  EXPECT_EQ(clamped, 1);
  const std::string obj = (dir / "r.obj").string();
  for (const char* material : {"scaled", "moved"})
    EXPECT_EQ(obj_error(dir, "r.obj", tri + "usemtl " + material + "\nf 1/1 2/1 3/1\n"),
              "OBJ '" + obj + "': material '" + material +
                  "': map_Kd's -s, -o and -t options are not supported (the texture coordinates are drawn as the vt "
                  "lines give them)");
  EXPECT_EQ(obj_error(dir, "r.obj", tri + "usemtl missing\nf 1/1 2/1 3/1\n"),
            "OBJ '" + obj + "': material 'missing': its map_Kd image 'nothere.png' is not there (" +
                (dir / "nothere.png").string() + ")");
  // CR alone as the line end: the same triangle as with LF.
  ASSERT_EQ(obj_error(dir, "cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r"), "");
  const Scene cr = load_obj_scene((dir / "cr.obj").string());
  ASSERT_EQ(cr.meshes.size(), 1u);
  EXPECT_EQ(cr.meshes[0].triangles.size(), 1u);
  EXPECT_EQ(cr.meshes[0].vertices[cr.meshes[0].triangles[0][1]].pos.x, 1.0);
  std::filesystem::remove_all(dir);
}

// Only the textures of materials that faces use are read: an unused material's image (here one
// the GPU cannot take) neither fails the load nor takes a texture index.
TEST(RefIo, OnlyTheTexturesOfUsedMaterialsAreLoaded) {
  const auto dir = std::filesystem::temp_directory_path() / "htx_ref_io_used";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kData + "/checker8x16.png", dir / "checker8x16.png",
                             std::filesystem::copy_options::overwrite_existing);
  Image odd;  // 12 x 4: refused if it were read
  odd.width = 12;
  odd.height = 4;
  odd.rgba.assign(12 * 4 * 4, 128);
  write_png((dir / "odd.png").string(), odd);
  std::ofstream(dir / "two.mtl") << "newmtl unused\nmap_Kd odd.png\nnewmtl used\nmap_Kd checker8x16.png\n";
  ASSERT_EQ(obj_error(dir, "two.obj", "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl used\nf 1/1 2/1 3/1\n"),
            "");
  const Scene s = load_obj_scene((dir / "two.obj").string());
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].log2_width, 3u);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_TRUE(s.meshes[0].state.textured);
  EXPECT_EQ(s.meshes[0].state.texture, 0);
  std::filesystem::remove_all(dir);
}

// Area averaging: 3 pixels into 2 cells of 1.5 pixels each, [a, b/2] and [b/2, c]; rows alike.
TEST(RefIo, ShrinkingAnImageAveragesTheAreaEachPixelCovers) {
  Image img;
  img.width = 3;
  img.height = 1;
  img.rgba = {0, 0, 0, 255, 90, 30, 3, 255, 180, 60, 9, 255};
  const Image out = shrink_image(img, 2, 1);
  ASSERT_EQ(out.width, 2);
  ASSERT_EQ(out.height, 1);
  // (0 + 90 / 2) / 1.5 = 30, (90 / 2 + 180) / 1.5 = 150; green 10 and 50; blue (1.5 / 1.5) = 1 and
  // (1.5 + 9) / 1.5 = 7; alpha stays 255.
  EXPECT_EQ(out.rgba, (std::vector<uint8_t>{30, 10, 1, 255, 150, 50, 7, 255}));
  const Image same = shrink_image(img, 3, 1);
  EXPECT_EQ(same.rgba, img.rgba) << "the same size is the image itself";
  EXPECT_THROW(shrink_image(img, 4, 1), std::invalid_argument);
  EXPECT_THROW(shrink_image(img, 0, 1), std::invalid_argument);
}

TEST(RefIo, HalvingAnImageAveragesEachTwoByTwoBlockRoundingHalvesUp) {
  Image img;
  img.width = 4;
  img.height = 2;
  img.rgba = {0, 0, 0, 0, 1, 1, 1, 1, 10, 20, 30, 40, 255, 255, 255, 255,  // top row
              1, 0, 0, 0, 0, 1, 1, 1, 11, 21, 31, 41, 255, 255, 255, 254};
  const Image half = halve_image(img);
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 1);
  // (0 + 1 + 1 + 0 + 2) >> 2 = 1 for red, (0 + 1 + 0 + 1 + 2) >> 2 = 1 for the others; then
  // (10 + 255 + 11 + 255 + 2) >> 2 = 133, ..., alpha (40 + 255 + 41 + 254 + 2) >> 2 = 148.
  EXPECT_EQ(half.rgba, (std::vector<uint8_t>{1, 1, 1, 1, 133, 138, 143, 148}));
  img.width = 3;
  EXPECT_THROW(halve_image(img), std::invalid_argument);
}

// A map_Kd image larger than the GPU takes is drawn from its largest mip level that fits, with a
// note; one whose every fitting level would have a side below 8 is refused; sides that are not
// powers of two are resampled first.
TEST(RefIo, ObjTexturesLargerThanTheGpuTakesAreHalvedUntilTheyFit) {
  const auto dir = std::filesystem::temp_directory_path() / "htx_ref_io_big_texture";
  std::filesystem::create_directories(dir);
  // NAME.obj, a textured triangle whose NAME.mtl maps NAME.png: a width x height image of hashed
  // bytes (constant 200 with flat).
  const auto write_textured = [&dir](const std::string& name, int width, int height, bool flat) {
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(static_cast<size_t>(width) * height * 4);
    for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = flat ? 200 : static_cast<uint8_t>((i * 2654435761u) >> 24);
    write_png((dir / (name + ".png")).string(), img);
    std::ofstream(dir / (name + ".mtl")) << "newmtl m\nmap_Kd " << name << ".png\n";
    std::ofstream(dir / (name + ".obj")) << "mtllib " << name
                                         << ".mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\n"
                                            "f 1/1 2/2 3/3\n";
  };
  write_textured("big", 1024, 512, false);
  write_textured("thin", 2048, 8, true);
  write_textured("npot", 600, 300, false);

  const Scene s = load_obj_scene((dir / "big.obj").string());
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].log2_width, 8u);
  EXPECT_EQ(s.textures[0].log2_height, 7u);
  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_NE(s.notes[0].find("is 1024x512: drawn from its 256x128 mip level"), std::string::npos) << s.notes[0];
  // Level 0 is the image halved twice, then made a texture as any other (bottom row first, RGB565).
  const Image quarter = halve_image(halve_image(load_image((dir / "big.png").string())));
  const Texture expected = texture_from_image(quarter, "expected");
  EXPECT_EQ(s.textures[0].levels[0], expected.levels[0]);

  try {
    load_obj_scene((dir / "thin.obj").string());
    ADD_FAILURE() << "a 2048x8 texture has no level with both sides in 8..256";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is 2048x8; no mip level of it"), std::string::npos) << e.what();
  }
  // Sides that are not powers of two: shrunk to the largest within them (area averaging), then
  // halved if still above 256: 600 x 300 -> 512 x 256 -> 256 x 128.
  const Scene n = load_obj_scene((dir / "npot.obj").string());
  ASSERT_EQ(n.textures.size(), 1u);
  EXPECT_EQ(n.textures[0].log2_width, 8u);
  EXPECT_EQ(n.textures[0].log2_height, 7u);
  ASSERT_EQ(n.notes.size(), 1u);
  EXPECT_NE(n.notes[0].find("is 600x300: resampled to 512x256 (the GPU takes sides that are powers of two), then "
                            "drawn from its 256x128 mip level"),
            std::string::npos)
      << n.notes[0];
  const Image expected_npot = halve_image(shrink_image(load_image((dir / "npot.png").string()), 512, 256));
  EXPECT_EQ(n.textures[0].levels[0], texture_from_image(expected_npot, "expected").levels[0]);
  // Within the GPU's sizes nothing changes and nothing is said.
  EXPECT_TRUE(load_obj_scene(kData + "/quad.obj").notes.empty());
  std::filesystem::remove_all(dir);
}

TEST(RefIo, PngRoundTripAndRgb565Expansion) {
  const Image img = image_from_rgb565(2, 1, {0xFFFF, 0x8410});
  EXPECT_EQ(img.rgba[0], 255);
  EXPECT_EQ(img.rgba[4], 0x84);  // 10000 -> 10000100
  EXPECT_EQ(img.rgba[5], 0x82);  // 100000 -> 10000010
  const auto path = (std::filesystem::temp_directory_path() / "htx_ref_io_roundtrip.png").string();
  write_png(path, img);
  const Image back = load_image(path);
  EXPECT_EQ(back.width, 2);
  EXPECT_EQ(back.rgba, img.rgba);
  std::remove(path.c_str());
  EXPECT_THROW(load_image(path), std::runtime_error);
}

TEST(RefIo, CompareImagesByHand) {
  Image a = image_from_rgb565(4, 1, {0, 0, 0, 0});
  Image b = a;
  EXPECT_TRUE(std::isinf(compare_images(a, b).psnr_db));
  b.rgba[0] = 10;  // one channel of one pixel off by 10: MSE = 100 / 12
  const ImageDiff d = compare_images(a, b);
  EXPECT_EQ(d.max_channel_diff, 10);
  EXPECT_EQ(d.differing_pixels, 1u);
  EXPECT_NEAR(d.psnr_db, 10 * std::log10(255.0 * 255.0 * 12 / 100), 1e-9);
  EXPECT_THROW(compare_images(a, image_from_rgb565(2, 2, {0, 0, 0, 0})), std::invalid_argument);
}

TEST(RefIo, ExactMismatchCountsColourAndDepthAndNamesTheFirst) {
  Frame a;
  a.width = 3;
  a.height = 2;
  a.color.assign(6, 7);
  a.depth.assign(6, 100);
  Frame b = a;
  EXPECT_EQ(exact_mismatch(a, b).pixels, 0u);
  EXPECT_EQ(exact_mismatch(a, b).first, "");
  b.depth[4] = 101;  // (1, 1)
  b.color[5] = 8;    // (2, 1)
  const FrameMismatch m = exact_mismatch(a, b);
  EXPECT_EQ(m.pixels, 2u);
  EXPECT_EQ(m.first, "(1, 1): colour 7 depth 100 against colour 7 depth 101");
  b.width = 6;
  b.height = 1;
  EXPECT_THROW(exact_mismatch(a, b), std::invalid_argument);
}

TEST(RefIo, MetricsAndJsonKeys) {
  Frame ref, eng;
  for (Frame* f : {&ref, &eng}) {
    f->width = 1000;
    f->height = 1;
    f->color.assign(1000, 0);
    f->probe.assign(1000, PixelProbe{});
  }
  for (int i = 0; i < 1000; ++i) {
    ref.probe[static_cast<size_t>(i)].covered = eng.probe[static_cast<size_t>(i)].covered = true;
    ref.probe[static_cast<size_t>(i)].level = 1;
    eng.probe[static_cast<size_t>(i)].u = i == 7 ? 4.0 : 0.002 * (i % 10);  // level-1 texels: halved
  }
  eng.probe[3].covered = false;  // one coverage difference
  eng.probe[5].mesh = 1;         // another mesh shown there: not compared, counted apart
  eng.probe[5].u = 100.0;
  eng.counters.divfree_steps_total = 30;
  eng.counters.divfree_pixels = 10;
  eng.counters.divfree_steps_max = 7;
  eng.counters.divfree_cap_hits = 2;
  const Metrics m = compute_metrics(eng, ref, {"model", "floor", "recip_nr", "bilinear", "full"});
  EXPECT_EQ(m.coverage_diff_pixels, 1u);
  EXPECT_EQ(m.surface_diff_pixels, 1u);
  EXPECT_EQ(m.compared_pixels, 998u);
  EXPECT_DOUBLE_EQ(m.max_texel_error, 2.0);
  EXPECT_DOUBLE_EQ(m.p999_texel_error, 2.0);  // rank ceil(0.999 * 998) = 998 of 998: the top one
  EXPECT_DOUBLE_EQ(m.divfree_mean_steps, 3.0);
  const nlohmann::json j = metrics_to_json(m);
  for (const char* key : {"max_texel_error", "rms_texel_error", "p999_texel_error", "psnr_db", "max_channel_diff",
                          "coverage_diff_pixels", "surface_diff_pixels", "divfree_max_steps", "divfree_mean_steps", "divfree_cap_hits",
                          "engine", "scene", "method", "filter", "config", "width", "height"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["psnr_db"].is_null());  // identical colours
  EXPECT_EQ(j["divfree_max_steps"], 7);
  EXPECT_EQ(j["scene"], "floor");
}

TEST(RefIo, Names) {
  EXPECT_EQ(parse_method("subdiv16").method, Method::Subdiv);
  EXPECT_EQ(parse_method("subdiv2").subdiv_n, 2u);
  EXPECT_THROW(parse_method("subdiv65"), std::invalid_argument);
  EXPECT_THROW(parse_method("subdiv"), std::invalid_argument);
  EXPECT_THROW(parse_method("subdiv8x"), std::invalid_argument);
  EXPECT_EQ(parse_method("divfree").method, Method::DivFree);
  EXPECT_EQ(method_name(Method::Subdiv, 8), "subdiv8");
  EXPECT_EQ(method_name(Method::RecipNr), "recip_nr");
  EXPECT_EQ(parse_filter("trilinear"), Filter::Trilinear);
  EXPECT_THROW(parse_filter("cubic"), std::invalid_argument);
  EXPECT_EQ(parse_wrap("mirror"), Wrap::Mirror);
  EXPECT_EQ(parse_depth_func("lequal"), DepthFunc::LEqual);
}

TEST(RefIo, SceneSpecsAreCheckedAndDeterministic) {
  EXPECT_THROW(make_builtin_scene("nosuch"), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("wsweep:r=1001"), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("wsweep:q=2"), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("wsweep:r"), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("wsweep:r=abc"), std::invalid_argument);
  EXPECT_THROW(make_builtin_scene("randmesh:count=2.5"), std::invalid_argument);
  // Numbers are decimal: hex, spaces, nan and inf are not numbers; one past a double is out of
  // range, and one below the smallest is its nearest double (stod threw for both).
  const auto error = [](const std::string& spec) -> std::string {
    try {
      make_builtin_scene(spec);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  for (const char* text : {"0x10", " 5", "5 ", "nan", "inf", "1e5x", "+-1"})
    EXPECT_EQ(error(std::string("cube:yaw=") + text), std::string("scene 'cube': parameter yaw='") + text + "' is not a number");
  EXPECT_EQ(error("cube:yaw=1e400").rfind("scene 'cube': parameter yaw=1e400 out of range [", 0), 0u) << error("cube:yaw=1e400");
  EXPECT_EQ(error("cube:yaw=-1e400").rfind("scene 'cube': parameter yaw=-1e400 out of range [", 0), 0u);
  EXPECT_EQ(error("cube:yaw=1e-400"), "");
  for (const SceneInfo& info : builtin_scenes()) {
    const ScreenScene a = prepare_screen_scene(make_builtin_scene(info.name), 160, 120);
    const ScreenScene b = prepare_screen_scene(make_builtin_scene(info.name), 160, 120);
    ASSERT_EQ(a.tris.size(), b.tris.size()) << info.name;
    EXPECT_GT(a.tris.size(), 0u) << info.name;
    for (size_t i = 0; i < a.tris.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a.tris[i].v[k].x, b.tris[i].v[k].x);
        EXPECT_EQ(a.tris[i].v[k].u, b.tris[i].v[k].u);
      }
    const Frame f = render_ref(a, {});
    EXPECT_GT(f.counters.pixels_written, 100u) << info.name;
  }
}

// `htx scenes` lists each parameter as the scene reads it: every listed bound is accepted, a step
// past it refused, and an integer parameter refuses a fraction.
TEST(RefIo, ListedSceneParametersAreTheOnesTheScenesTake) {
  EXPECT_EQ(describe_scene_params(builtin_scenes().front().params),
            "pitch=8 (0.5..60 deg down), height=1 (0.05..10 eye height), grid=8 (1..64 quads a side)");
  size_t listed = 0;
  for (const SceneInfo& info : builtin_scenes()) {
    ASSERT_FALSE(info.params.empty()) << info.name;
    for (const SceneParamInfo& p : info.params) {
      ++listed;
      const auto spec = [&](double v) {
        char text[48];
        std::snprintf(text, sizeof text, "%.10g", v);
        return info.name + ":" + p.key + "=" + text;
      };
      EXPECT_GE(p.fallback, p.min) << info.name << " " << p.key;
      EXPECT_LE(p.fallback, p.max) << info.name << " " << p.key;
      const double step = p.integer ? 1.0 : (p.max - p.min) * 1e-3;
      EXPECT_NO_THROW(make_builtin_scene(spec(p.min))) << spec(p.min);
      EXPECT_NO_THROW(make_builtin_scene(spec(p.max))) << spec(p.max);
      EXPECT_THROW(make_builtin_scene(spec(p.min - step)), std::invalid_argument) << spec(p.min - step);
      EXPECT_THROW(make_builtin_scene(spec(p.max + step)), std::invalid_argument) << spec(p.max + step);
      if (p.integer) {
        EXPECT_THROW(make_builtin_scene(spec(p.fallback + 0.5)), std::invalid_argument) << info.name;
      }
    }
  }
  EXPECT_EQ(listed, 23u);
}

}  // namespace
}  // namespace htx
