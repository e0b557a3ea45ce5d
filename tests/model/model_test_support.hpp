// Helpers shared by the ref_* and accuracy_* tests: build a scene's screen form with every triangle's
// method and filter forced, and the lists of built-in scene specs the accuracy targets cover.
#pragma once

#include <string>
#include <vector>

#include "htx/model/geometry.hpp"
#include "htx/model/scenes.hpp"
#include "htx/model/types.hpp"

namespace htx::test {

inline ScreenScene screen_with(const std::string& spec, Method method, Filter filter, int width = 320,
                               int height = 240, unsigned subdiv_n = 16) {
  ScreenScene s = prepare_screen_scene(make_builtin_scene(spec), width, height);
  for (ScreenTri& t : s.tris) {
    t.state.method = method;
    t.state.subdiv_n = subdiv_n;
    t.state.filter = filter;
  }
  return s;
}

// Every built-in scene, with the extremes the acceptance names (depth ratio 1000, |u| up to 2^14).
inline std::vector<std::string> accuracy_scene_specs() {
  return {"floor",        "cube",      "tunnel", "wsweep:r=1",    "wsweep:r=100", "wsweep:r=1000",
          "nearclip",     "slivers",   "bigtri", "wrap",          "wrap:offset=16384,tilt=60",
          "pan:step=1",   "pan:step=129", "randmesh"};
}

}  // namespace htx::test
