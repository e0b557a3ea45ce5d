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
#include <string_view>
#include <utility>
#include <vector>

#include "htx/host/file_in.hpp"
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

// A UTF-8 byte-order mark, which some Windows editors put first: tinyobjloader would read the first
// line's keyword as "\xEF\xBB\xBFv" and drop that line, shifting every later vertex index. It is
// stripped from the OBJ and from each MTL.
constexpr std::string_view kBom = "\xEF\xBB\xBF";

// The whole file, without a leading byte-order mark: a regular file of at most
// kMaxSceneFileBytes, and text (a NUL byte would also cut the error messages that quote a word).
std::string read_text(const std::filesystem::path& file) {
  std::string s;
  try {
    s = host::read_regular_file(file.string(), kMaxSceneFileBytes);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("cannot read '" + file.string() + "': " + e.what());
  }
  if (const size_t nul = s.find('\0'); nul != std::string::npos)
    throw std::runtime_error("'" + file.string() + "' line " +
                             std::to_string(1 + std::count(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(nul), '\n')) +
                             ": a NUL byte (not a text file)");
  if (s.starts_with(kBom)) s.erase(0, kBom.size());
  // Classic Mac OS line ends (CR alone, in a file without LF) are line ends: tinyobjloader read
  // such a file as one line. (In a file with LF a stray CR stays, so line numbers stay an editor's.)
  if (s.find('\n') == std::string::npos) std::replace(s.begin(), s.end(), '\r', '\n');
  return s;
}

// Calls visit(line number, keyword, the words after it) for each line of `file` (comments cut).
template <class Visit>
void for_each_line(const std::filesystem::path& file, Visit visit) {
  std::istringstream in(read_text(file));
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

// Every word a decimal number finite as a float (tinyobjloader stores floats: 1e39 would be
// infinite) and their count one the format allows: otherwise a clear error naming the file and
// line, instead of tinyobjloader's silent 0 (a Kd of one number, which the MTL format reads as
// grey, it reads as red: three are required).
void check_decimals(const std::string& source, size_t line, const std::string& keyword,
                    const std::vector<std::string>& words, bool count_ok, const char* counts) {
  const std::string where = source + " line " + std::to_string(line) + ": ";
  for (const std::string& w : words) {
    if (!is_decimal(w)) throw std::runtime_error(where + "'" + w + "' is not a finite decimal number");
    if (!std::isfinite(std::strtof(w.c_str(), nullptr)))
      throw std::runtime_error(where + "'" + w + "' is not a finite decimal number as a float (at most about 3.4e38)");
  }
  if (!count_ok)
    throw std::runtime_error(where + "'" + keyword + "' with " + std::to_string(words.size()) + " numbers (" +
                             counts + ")");
}

// One kind of face index (v, vt or vn): the lines of its kind in the file and before the face.
struct IndexKind {
  const char* keyword;
  const char* name;
  int total = 0, so_far = 0;
};

// A face corner's index: a non-zero integer naming a line of its kind, counted from the first
// (positive, any line of the file, as tinyobjloader takes them) or back from the face (negative).
// tinyobjloader reads a relative index before the first line as a negative index, which is taken
// as (0, 0) for a texture coordinate, so each is checked here, where the line is known.
void check_index(const std::string& where, const std::string& word, const IndexKind& kind) {
  const size_t sign = word.starts_with('-') || word.starts_with('+') ? 1 : 0;
  const bool integer = word.size() > sign && word.size() - sign <= 9 &&
                       std::all_of(word.begin() + static_cast<std::ptrdiff_t>(sign), word.end(),
                                   [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)) != 0; });
  if (!integer) throw std::runtime_error(where + "'" + word + "' is not a " + kind.name + " index");
  const int k = std::stoi(word);
  const auto lines = [&kind](int n) { return std::to_string(n) + " " + kind.keyword + " line" + (n == 1 ? "" : "s"); };
  if (k > kind.total)
    throw std::runtime_error(where + kind.name + " index " + word + " out of range (the file has " + lines(kind.total) + ")");
  if (k == 0 || -k > kind.so_far)
    throw std::runtime_error(where + kind.name + " index " + word + " out of range (" + lines(kind.so_far) +
                             " before it)");
}

// A face line: at least 3 corners, each v, v/vt, v//vn or v/vt/vn with its indices in range, and
// texture coordinates at every corner or at none (a corner without them would take (0, 0)).
void check_face(const std::string& where, const std::vector<std::string>& corners, IndexKind* kinds) {
  if (corners.size() < 3)
    throw std::runtime_error(where + "a face with " + std::to_string(corners.size()) +
                             " corners (a face has 3 or more)");
  size_t with_vt = 0;
  for (const std::string& corner : corners) {
    std::vector<std::string> parts;
    for (size_t at = 0;; ++at) {
      const size_t slash = corner.find('/', at);
      parts.push_back(corner.substr(at, slash - at));
      if (slash == std::string::npos) break;
      at = slash;
    }
    if (parts.size() > 3 || parts[0].empty() || (parts.size() == 2 && parts[1].empty()) ||
        (parts.size() == 3 && parts[2].empty()))
      throw std::runtime_error(where + "'" + corner + "' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
    for (size_t k = 0; k < parts.size(); ++k)
      if (!parts[k].empty()) check_index(where, parts[k], kinds[k]);
    if (parts.size() > 1 && !parts[1].empty()) ++with_vt;
  }
  if (with_vt != 0 && with_vt != corners.size())
    throw std::runtime_error(where + "a face with texture coordinates at " + std::to_string(with_vt) + " of its " +
                             std::to_string(corners.size()) + " corners (OBJ gives them at every corner or none)");
}

// What tinyobjloader lets pass with at most a warning, checked before it reads the file: the
// numbers of v and vt lines and of the material libraries' Kd lines, each face's corners and
// indices, that each material library exists and that each usemtl names a material of a library
// given before it (tinyobjloader draws an unknown one white). Adds each material library's path
// to `libraries`.
void check_obj_text(const std::string& path, std::vector<std::string>* libraries) {
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  IndexKind kinds[3] = {{"v", "vertex"}, {"vt", "texture coordinate"}, {"vn", "normal"}};
  for_each_line(path, [&](size_t, const std::string& key, const std::vector<std::string>&) {
    for (IndexKind& kind : kinds) kind.total += key == kind.keyword;
  });
  std::set<std::string> materials;  // those of the libraries given so far
  for_each_line(path, [&](size_t n, const std::string& key, const std::vector<std::string>& w) {
    const size_t c = w.size();
    const std::string where = "OBJ '" + path + "' line " + std::to_string(n) + ": ";
    for (IndexKind& kind : kinds) kind.so_far += key == kind.keyword;
    if (key == "v") {
      check_decimals("OBJ '" + path + "'", n, key, w, c == 3 || c == 4 || c == 6 || c == 7, "v takes 3, 4, 6 or 7");
    } else if (key == "vt") {
      check_decimals("OBJ '" + path + "'", n, key, w, c >= 1 && c <= 3, "vt takes 1 to 3");
    } else if (key == "f") {
      check_face(where, w, kinds);
    } else if (key == "usemtl" && c > 0) {
      if (!materials.contains(w[0]))
        throw std::runtime_error(where + "usemtl '" + w[0] + "' is in none of the material libraries before it");
    } else if (key == "mtllib") {
      for (const std::string& lib : w) {
        const std::filesystem::path file = dir / lib;
        if (!std::filesystem::is_regular_file(file))
          throw std::runtime_error(where + "material library '" + lib + "' not found");
        libraries->push_back(file.string());
        for_each_line(file, [&](size_t m, const std::string& mkey, const std::vector<std::string>& mw) {
          if (mkey == "Kd")
            check_decimals("MTL '" + file.string() + "'", m, mkey, mw, mw.size() == 3, "Kd takes 3");
          else if (mkey == "newmtl" && !mw.empty())
            materials.insert(mw[0]);
        });
      }
    }
  });
}

// tinyobjloader's material libraries, read from the OBJ's directory without a byte-order mark.
class MaterialLibraryReader : public tinyobj::MaterialReader {
 public:
  explicit MaterialLibraryReader(std::filesystem::path dir) : dir_(std::move(dir)) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* by_name, std::string* warn, std::string* err) override {
    const std::filesystem::path file = dir_ / name;
    if (!std::filesystem::is_regular_file(file)) {
      *warn += "Material file [ " + name + " ] not found\n";
      return false;
    }
    std::istringstream text(read_text(file));
    tinyobj::LoadMtl(by_name, materials, &text, warn, err);
    return true;
  }

 private:
  std::filesystem::path dir_;
};

// tinyobjloader's warnings that lose nothing the loader draws (it keeps `d` over `Tr`; a group
// without a name, an mtllib without a file). Any other drops a face or a material: an error.
bool harmless_warning(const std::string& line) {
  for (const char* harmless : {"Both `d` and `Tr`", "Empty group name", "Looks like empty filename for mtllib"})
    if (line.find(harmless) != std::string::npos) return true;
  return line.empty() || line == ".";
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
  std::vector<std::string> libraries;
  check_obj_text(path, &libraries);
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream text(read_text(path));
  MaterialLibraryReader library_reader(dir);
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &text, &library_reader, /*triangulate=*/true,
                        /*default_vcols_fallback=*/true))
    throw std::runtime_error("cannot load OBJ '" + path + "': " + err);
  // What the checks above do not foresee and tinyobjloader drops with only a warning (a face, a
  // material) is refused too, with its words.
  std::istringstream warnings(warn);
  for (std::string line; std::getline(warnings, line);)
    if (!harmless_warning(line)) throw std::runtime_error("OBJ '" + path + "': " + line);

  Scene scene;
  scene.name = std::filesystem::path(path).filename().string();
  scene.sources.push_back(path);
  scene.sources.insert(scene.sources.end(), libraries.begin(), libraries.end());
  // Only the textures of materials a face uses: an unused material's image is neither read nor sent.
  std::vector<bool> used(materials.size(), false);
  for (const auto& shape : shapes)
    for (const int m : shape.mesh.material_ids)
      if (m >= 0 && static_cast<size_t>(m) < materials.size()) used[static_cast<size_t>(m)] = true;
  std::map<std::string, int> texture_index;  // by file name
  std::vector<int> material_texture(materials.size(), -1);
  for (size_t m = 0; m < materials.size(); ++m) {
    const std::string& tex = materials[m].diffuse_texname;
    if (tex.empty() || !used[m]) continue;
    const std::string full = (dir / tex).string();
    const std::string material = "OBJ '" + path + "': material '" + materials[m].name + "'";
    if (!std::filesystem::exists(full))
      throw std::runtime_error(material + ": its map_Kd image '" + tex + "' is not there (" + full + ")");
    // The options that move or repeat the image on the surface are not drawn: refused, not dropped.
    const tinyobj::texture_option_t& opt = materials[m].diffuse_texopt;
    for (int k = 0; k < 3; ++k) {
      if (opt.scale[k] != 1 || opt.origin_offset[k] != 0 || opt.turbulence[k] != 0)
        throw std::runtime_error(material + ": map_Kd's -s, -o and -t options are not supported (the texture "
                                 "coordinates are drawn as the vt lines give them)");
    }
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
  for (const auto& shape : shapes) {
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
        // map_Kd's -clamp on: clamped at the edges (the texture unit's clamp), else repeated.
        if (mat >= 0 && materials[static_cast<size_t>(mat)].diffuse_texopt.clamp)
          mesh.state.wrap_u = mesh.state.wrap_v = Wrap::Clamp;
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
    for (const Vertex& v : mesh.vertices) {
      if (!std::isfinite(v.pos.x) || !std::isfinite(v.pos.y) || !std::isfinite(v.pos.z))
        throw std::runtime_error("OBJ '" + path + "' has a non-finite vertex");
      if (!std::isfinite(v.s) || !std::isfinite(v.t))
        throw std::runtime_error("OBJ '" + path + "' has a non-finite texture coordinate");
      if (!std::isfinite(v.r) || !std::isfinite(v.g) || !std::isfinite(v.b))
        throw std::runtime_error("OBJ '" + path + "' has a non-finite colour");
    }

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
