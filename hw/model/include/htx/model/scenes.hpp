// Built-in scenes (deterministic, parameterised) and scene loading by name or file.
// A scene spec is `name` or `name:key=value,key=value` (e.g. `wsweep:r=100`); see docs/scenes.md.
#pragma once

#include <string>
#include <vector>

#include "htx/model/scene.hpp"

namespace htx {

struct SceneInfo {
  std::string name;
  std::string description;  // one line
  std::string params;       // "key=default (meaning), ..." or empty
};

const std::vector<SceneInfo>& builtin_scenes();

// Builds a built-in scene. Throws std::invalid_argument for an unknown name, an unknown parameter or
// a value out of its documented range.
Scene make_builtin_scene(const std::string& spec);

// A spec ending in .obj (any case) loads the OBJ file, anything else is a built-in scene.
Scene load_scene(const std::string& spec_or_path);

}  // namespace htx
