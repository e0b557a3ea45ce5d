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
#include <sstream>
#include <stdexcept>
#include <utility>

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

// Every number of the vertex (v: x y z, optionally w or r g b) and texture-coordinate (vt: u,
// optionally v and w) lines is a finite decimal, and each line has a count the format allows:
// otherwise a clear error naming the line, instead of tinyobjloader's silent 0.
void check_obj_numbers(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string keyword, tok;
    words >> keyword;
    if (keyword != "v" && keyword != "vt") continue;
    size_t count = 0;
    while (words >> tok) {
      ++count;
      if (!is_decimal(tok) || !std::isfinite(std::strtod(tok.c_str(), nullptr)))
        throw std::runtime_error("OBJ '" + path + "' line " + std::to_string(number) + ": '" + tok +
                                 "' is not a finite decimal number");
    }
    const bool ok = keyword == "v" ? (count == 3 || count == 4 || count == 6 || count == 7) : (count >= 1 && count <= 3);
    if (!ok)
      throw std::runtime_error("OBJ '" + path + "' line " + std::to_string(number) + ": '" + keyword + "' with " +
                               std::to_string(count) + " numbers (v takes 3, 4, 6 or 7; vt 1 to 3)");
  }
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
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = true;
  config.mtl_search_path = std::filesystem::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config) || !reader.Valid())
    throw std::runtime_error("cannot load OBJ '" + path + "': " + reader.Error());
  check_obj_numbers(path);
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto& materials = reader.GetMaterials();

  Scene scene;
  scene.name = std::filesystem::path(path).filename().string();
  std::map<std::string, int> texture_index;  // by file name
  std::vector<int> material_texture(materials.size(), -1);
  for (size_t m = 0; m < materials.size(); ++m) {
    const std::string& tex = materials[m].diffuse_texname;
    if (tex.empty()) continue;
    const std::string full = (std::filesystem::path(config.mtl_search_path) / tex).string();
    auto it = texture_index.find(full);
    if (it == texture_index.end()) {
      scene.textures.push_back(texture_from_image(load_image(full), full));
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
        if (ix.texcoord_index >= 0 && static_cast<size_t>(ix.texcoord_index) * 2 + 1 < attrib.texcoords.size()) {
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
