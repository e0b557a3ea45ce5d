// The list of built-in scenes and the dispatch from a scene spec to its constructor.
#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "builtin_makers.hpp"
#include "htx/model/obj_loader.hpp"
#include "htx/model/scenes.hpp"

namespace htx {

namespace {

struct Entry {
  const char* name;
  const char* description;  // one line
  Scene (*make)(SceneParams&);
};

const std::vector<Entry>& registry() {
  static const std::vector<Entry> entries = {
      {"floor", "checkerboard plane at a grazing angle, out to the horizon", scenes::make_floor},
      {"cube", "reference 002's cube: a 64x64 checkerboard on every face, in perspective", scenes::make_cube},
      {"tunnel", "inside a long textured cylinder, darkening with depth", scenes::make_tunnel},
      {"wsweep", "one triangle spanning du texels from depth w to r*w (affine error study)", scenes::make_wsweep},
      {"nearclip", "triangles crossing the near plane, one or two vertices behind the camera", scenes::make_nearclip},
      {"slivers", "a fan of thin triangles sharing edges, plus sub-pixel needles", scenes::make_slivers},
      {"bigtri", "triangles hundreds of screens wide, some reaching behind the camera", scenes::make_bigtri},
      {"wrap", "texture coordinates up to +-2^14 texels, repeat/mirror/clamp, tilted", scenes::make_wrap},
      {"pan", "magnified texture panned by step/256 texel", scenes::make_pan},
      {"randmesh", "random closed meshes (convex hulls on random ellipsoids), seeded", scenes::make_randmesh},
  };
  return entries;
}

bool ends_with_obj(const std::string& s) {
  if (s.size() < 4) return false;
  std::string tail = s.substr(s.size() - 4);
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return std::tolower(c); });
  return tail == ".obj";
}

}  // namespace

const std::vector<SceneInfo>& builtin_scenes() {
  static const std::vector<SceneInfo> infos = [] {
    // Each scene's parameters as its maker asks for them, read by making it with the defaults.
    std::vector<SceneInfo> v;
    for (const Entry& e : registry()) {
      SceneParams defaults(e.name);
      e.make(defaults);
      v.push_back({e.name, e.description, defaults.asked()});
    }
    return v;
  }();
  return infos;
}

Scene make_builtin_scene(const std::string& spec) {
  SceneParams params(spec);
  for (const Entry& e : registry()) {
    if (e.name != params.name()) continue;
    Scene s = e.make(params);
    params.check_all_used();
    s.name = spec;
    return s;
  }
  if (ends_with_obj(params.name()))
    throw std::invalid_argument("'" + spec + "': an OBJ file takes no parameters (the built-in scenes do)");
  std::string names;
  for (const Entry& e : registry()) names += (names.empty() ? "" : ", ") + std::string(e.name);
  throw std::invalid_argument("unknown scene '" + params.name() + "' (built-in: " + names + "; or a .obj file)");
}

Scene load_scene(const std::string& spec_or_path) {
  if (ends_with_obj(spec_or_path)) return load_obj_scene(spec_or_path);
  return make_builtin_scene(spec_or_path);
}

}  // namespace htx
