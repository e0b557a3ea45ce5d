// htx scenes: the built-in scenes, one line each, with their parameters.
#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "htx/model/scenes.hpp"

namespace htx {

void register_scenes(CLI::App& app) {
  auto* cmd = app.add_subcommand("scenes", "List the built-in scenes (use as NAME or NAME:key=value,...)");
  cmd->callback([] {
    for (const SceneInfo& s : builtin_scenes()) {
      std::cout << std::left << std::setw(10) << s.name << s.description << "\n";
      if (!s.params.empty()) std::cout << std::setw(10) << "" << describe_scene_params(s.params) << "\n";
    }
    std::cout << "Any FILE.obj (with its MTL and PNG textures) renders as a scene too.\n";
  });
}

}  // namespace htx
