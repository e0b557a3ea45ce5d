// Built-in scenes (deterministic, parameterised) and scene loading by name or file.
// A scene spec is `name` or `name:key=value,key=value` (e.g. `wsweep:r=100`); see docs/scenes.md.
#pragma once

#include <string>
#include <vector>

#include "htx/model/scene.hpp"

namespace htx {

// A scene parameter as the scene reads it (so the listing and the parsing cannot drift apart).
struct SceneParamInfo {
  std::string key;
  double fallback, min, max;
  bool integer;
  std::string unit;  // what the number counts, or empty
};

struct SceneInfo {
  std::string name;
  std::string description;  // one line
  std::vector<SceneParamInfo> params;
};

// "key=default (min..max unit), ..." (empty for no parameters).
std::string describe_scene_params(const std::vector<SceneParamInfo>& params);

const std::vector<SceneInfo>& builtin_scenes();

// Builds a built-in scene. Throws std::invalid_argument for an unknown name, an unknown parameter or
// a value out of its documented range.
Scene make_builtin_scene(const std::string& spec);

// A spec ending in .obj (any case) loads the OBJ file, anything else is a built-in scene.
Scene load_scene(const std::string& spec_or_path);

}  // namespace htx
