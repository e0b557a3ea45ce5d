#include "htx/model/obj_loader.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "htx/model/image_io.hpp"
#include "htx/model/texture.hpp"

namespace htx {

namespace {

unsigned log2_exact(int n) {
  unsigned l = 0;
  while ((1 << l) < n) ++l;
  return (1 << l) == n ? l : 0;
}

// A decimal number as OBJ writes them: [+-] digits [. digits] [(e|E) [+-] digits], with a digit
// before or after the point. tinyobjloader reads anything else (nan, inf, hex, a word) as 0
// without a warning, so a corrupt coordinate would silently move a vertex to the origin.
bool is_decimal(const std::string& tok) {
  size_t i = 0;
  if (i < tok.size() && (tok[i] == '+' || tok[i] == '-')) ++i;
  size_t digits = 0;
  while (i < tok.size() && std::isdigit(static_cast<unsigned char>(tok[i]))) ++i, ++digits;
  if (i < tok.size() && tok[i] == '.') {
    ++i;
    while (i < tok.size() && std::isdigit(static_cast<unsigned char>(tok[i]))) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < tok.size() && (tok[i] == 'e' || tok[i] == 'E')) {
    ++i;
    if (i < tok.size() && (tok[i] == '+' || tok[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < tok.size() && std::isdigit(static_cast<unsigned char>(tok[i]))) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == tok.size();
}

// Calls visit(line number, keyword, the words after it) for each line of `file` (comments cut).
template <class Visit>
void for_each_line(const std::filesystem::path& file, Visit visit) {
  std::ifstream in(file);
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream stream(line.substr(0, line.find('#')));
    std::string keyword, word;
    std::vector<std::string> words;
    stream >> keyword;
    while (stream >> word) words.push_back(word);
    visit(number, keyword, words);
  }
}

// Every word a finite decimal number and their count one the format allows: otherwise a clear
// error naming the file and line, instead of tinyobjloader's silent 0 (a Kd of one number, which
// the MTL format reads as grey, it reads as red: three are required).
void check_decimals(const std::string& source, size_t line, const std::string& keyword,
                    const std::vector<std::string>& words, bool count_ok, const char* counts) {
  const std::string where = source + " line " + std::to_string(line) + ": ";
  for (const std::string& w : words)
    if (!is_decimal(w) || !std::isfinite(std::strtod(w.c_str(), nullptr)))
      throw std::runtime_error(where + "'" + w + "' is not a finite decimal number");
  if (!count_ok)
    throw std::runtime_error(where + "'" + keyword + "' with " + std::to_string(words.size()) + " numbers (" +
                             counts + ")");
}

// What tinyobjloader lets pass with at most a warning, checked before it reads the file: the
// numbers of v and vt lines and of the material libraries' Kd lines, and that each material
// library exists. Returns the material names the OBJ's usemtl lines ask for; adds each material
// library's path to `libraries`.
std::set<std::string> check_obj_text(const std::string& path, std::vector<std::string>* libraries) {
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::set<std::string> used;
  for_each_line(path, [&](size_t n, const std::string& key, const std::vector<std::string>& w) {
    const size_t c = w.size();
    if (key == "v") {
      check_decimals("OBJ '" + path + "'", n, key, w, c == 3 || c == 4 || c == 6 || c == 7, "v takes 3, 4, 6 or 7");
    } else if (key == "vt") {
      check_decimals("OBJ '" + path + "'", n, key, w, c >= 1 && c <= 3, "vt takes 1 to 3");
    } else if (key == "usemtl" && c > 0) {
      used.insert(w[0]);
    } else if (key == "mtllib") {
      for (const std::string& lib : w) {
        const std::filesystem::path file = dir / lib;
        if (!std::filesystem::is_regular_file(file))
          throw std::runtime_error("OBJ '" + path + "' line " + std::to_string(n) + ": material library '" + lib +
                                   "' not found");
        libraries->push_back(file.string());
        for_each_line(file, [&](size_t m, const std::string& mkey, const std::vector<std::string>& mw) {
          if (mkey == "Kd")
            check_decimals("MTL '" + file.string() + "'", m, mkey, mw, mw.size() == 3, "Kd takes 3");
        });
      }
    }
  });
  return used;
}

// The largest power of two not above n (n >= 1).
int floor_pow2(int n) {
  int p = 1;
  while (p <= n / 2) p *= 2;
  return p;
}

// A map_Kd image the texture unit cannot take as it is becomes one it can, and `note` says how:
// sides that are not powers of two are shrunk to the largest powers of two within them (area
// averaging), and a side above 256 texels is brought within it by halving the image, as its mip
// levels are made, so that a model's usual 1024 x 1024 texture draws from its 256 x 256 level.
// An image with no such form whose sides are both at least 8 is refused.
Image fit_texture_image(Image img, const std::string& path, std::string* note) {
  const std::string size = std::to_string(img.width) + "x" + std::to_string(img.height);
  if (img.width < 1 || img.height < 1) throw std::runtime_error("texture '" + path + "' is empty");
  std::string resampled, halved;
  if (floor_pow2(img.width) != img.width || floor_pow2(img.height) != img.height) {
    img = shrink_image(img, floor_pow2(img.width), floor_pow2(img.height));
    resampled = "resampled to " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                " (the GPU takes sides that are powers of two)";
  }
  constexpr int kMin = 1 << kMinTexLog2, kMax = 1 << kMaxTexLog2;
  while ((img.width > kMax || img.height > kMax) && img.width > kMin && img.height > kMin) {
    img = halve_image(img);
    halved = "drawn from its " + std::to_string(img.width) + "x" + std::to_string(img.height) +
             " mip level (the GPU takes sides up to 256)";
  }
  if (img.width < kMin || img.height < kMin || img.width > kMax || img.height > kMax)
    throw std::runtime_error("texture '" + path + "' is " + size +
                             "; no mip level of it (or of its power-of-two form) has both sides in 8..256");
  if (!resampled.empty() || !halved.empty())
    *note = "texture '" + path + "' is " + size + ": " + resampled + (resampled.empty() || halved.empty() ? "" : ", then ") +
            halved;
  return img;
}

}  // namespace

Texture texture_from_image(const Image& img, const std::string& path, TexFormat format) {
  const unsigned lw = log2_exact(img.width), lh = log2_exact(img.height);
  if (lw < kMinTexLog2 || lw > kMaxTexLog2 || lh < kMinTexLog2 || lh > kMaxTexLog2)
    throw std::runtime_error("texture '" + path + "' is " + std::to_string(img.width) + "x" +
                             std::to_string(img.height) + "; sides must be powers of two in 8..256");
  // Image rows are top-down, texel row 0 is v = 0 (the image bottom in OBJ's convention).
  std::vector<uint8_t> rows(img.rgba.size());
  const size_t stride = static_cast<size_t>(img.width) * 4;
  for (int y = 0; y < img.height; ++y)
    std::copy_n(&img.rgba[static_cast<size_t>(img.height - 1 - y) * stride], stride, &rows[y * stride]);
  return make_texture(format, lw, lh, rows);
}

Scene load_obj_scene(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("OBJ '" + path + "': " + (std::filesystem::exists(path) ? "not a file" : "no such file"));
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = true;
  config.mtl_search_path = std::filesystem::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config) || !reader.Valid())
    throw std::runtime_error("cannot load OBJ '" + path + "': " + reader.Error());
  std::vector<std::string> libraries;
  const std::set<std::string> used_materials = check_obj_text(path, &libraries);
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto& materials = reader.GetMaterials();
  for (const std::string& name : used_materials) {
    const auto named = [&name](const tinyobj::material_t& m) { return m.name == name; };
    if (std::none_of(materials.begin(), materials.end(), named))
      throw std::runtime_error("OBJ '" + path + "': usemtl '" + name + "' is in none of its material libraries");
  }

  Scene scene;
  scene.name = std::filesystem::path(path).filename().string();
  scene.sources.push_back(path);
  scene.sources.insert(scene.sources.end(), libraries.begin(), libraries.end());
  std::map<std::string, int> texture_index;  // by file name
  std::vector<int> material_texture(materials.size(), -1);
  for (size_t m = 0; m < materials.size(); ++m) {
    const std::string& tex = materials[m].diffuse_texname;
    if (tex.empty()) continue;
    const std::string full = (std::filesystem::path(config.mtl_search_path) / tex).string();
    auto it = texture_index.find(full);
    if (it == texture_index.end()) {
      std::string note;
      scene.textures.push_back(texture_from_image(fit_texture_image(load_image(full), full, &note), full));
      scene.sources.push_back(full);
      if (!note.empty()) scene.notes.push_back(note);
      it = texture_index.emplace(full, static_cast<int>(scene.textures.size()) - 1).first;
    }
    material_texture[m] = it->second;
  }

  const size_t nverts = attrib.vertices.size() / 3;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-lo.x, -lo.y, -lo.z};
  for (const auto& shape : reader.GetShapes()) {
    std::map<int, Mesh> by_material;
    const auto& idx = shape.mesh.indices;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      if (shape.mesh.num_face_vertices[f] != 3) throw std::runtime_error("OBJ '" + path + "': face not triangulated");
      const int mat = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      if (mat >= static_cast<int>(materials.size())) throw std::runtime_error("OBJ '" + path + "': bad material id");
      auto [it, fresh] = by_material.try_emplace(mat);
      Mesh& mesh = it->second;
      if (fresh) {
        mesh.name = shape.name;
        mesh.state.texture = mat >= 0 ? material_texture[static_cast<size_t>(mat)] : -1;
        mesh.state.textured = mesh.state.texture >= 0;
        if (!mesh.state.textured) mesh.state.texture = 0;
      }
      std::array<uint32_t, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t& ix = idx[f * 3 + static_cast<size_t>(k)];
        if (ix.vertex_index < 0 || static_cast<size_t>(ix.vertex_index) >= nverts)
          throw std::runtime_error("OBJ '" + path + "': vertex index out of range");
        const auto vi = static_cast<size_t>(ix.vertex_index);
        Vertex v;
        v.pos = {attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]};
        if (ix.texcoord_index >= 0) {
          if (static_cast<size_t>(ix.texcoord_index) * 2 + 1 >= attrib.texcoords.size())
            throw std::runtime_error("OBJ '" + path + "': texture coordinate index out of range");
          v.s = attrib.texcoords[2 * static_cast<size_t>(ix.texcoord_index)];
          v.t = attrib.texcoords[2 * static_cast<size_t>(ix.texcoord_index) + 1];
        }
        double kd[3] = {1, 1, 1};
        if (mat >= 0)
          for (int c = 0; c < 3; ++c) kd[c] = materials[static_cast<size_t>(mat)].diffuse[c];
        const bool has_colors = attrib.colors.size() >= 3 * nverts;
        v.r = kd[0] * (has_colors ? attrib.colors[3 * vi] : 1);
        v.g = kd[1] * (has_colors ? attrib.colors[3 * vi + 1] : 1);
        v.b = kd[2] * (has_colors ? attrib.colors[3 * vi + 2] : 1);
        lo = {std::min(lo.x, v.pos.x), std::min(lo.y, v.pos.y), std::min(lo.z, v.pos.z)};
        hi = {std::max(hi.x, v.pos.x), std::max(hi.y, v.pos.y), std::max(hi.z, v.pos.z)};
        tri[static_cast<size_t>(k)] = static_cast<uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(v);
      }
      mesh.triangles.push_back(tri);
    }
    for (auto& [mat, mesh] : by_material) scene.meshes.push_back(std::move(mesh));
  }
  if (scene.meshes.empty()) throw std::runtime_error("OBJ '" + path + "' has no faces");
  for (const auto& mesh : scene.meshes)
    for (const Vertex& v : mesh.vertices)
      if (!std::isfinite(v.pos.x) || !std::isfinite(v.pos.y) || !std::isfinite(v.pos.z))
        throw std::runtime_error("OBJ '" + path + "' has a non-finite vertex");

  const Vec3 centre = (lo + hi) * 0.5;
  const double radius = std::max(length(hi - lo) * 0.5, 1e-6);
  const double distance = radius / std::sin(scene.camera.fovy_radians / 2) * 1.05;
  scene.camera.target = centre;
  scene.camera.eye = centre + normalize(Vec3{0, 0.35, 1}) * distance;
  scene.camera.near_plane = std::max(distance - radius * 1.5, distance * 0.01);
  scene.camera.far_plane = distance + radius * 1.5;
  return scene;
}

}  // namespace htx
