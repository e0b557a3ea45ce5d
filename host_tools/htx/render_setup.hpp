// What `htx render` does to a scene before an engine draws it, shared with `htx crosscheck` so that
// a case it reports is the render its reproduction command makes.
#pragma once

#include <string>

#include "htx/model/config.hpp"
#include "htx/model/names.hpp"
#include "htx/model/types.hpp"

namespace htx {

// --untextured, --method and --filter (empty: the scene's own) applied to every triangle.
inline void override_triangle_states(ScreenScene& screen, const std::string& method, const std::string& filter,
                                     bool untextured) {
  if (untextured)
    for (ScreenTri& t : screen.tris) t.state.textured = false;
  if (!method.empty()) {
    const MethodChoice m = parse_method(method);
    for (ScreenTri& t : screen.tris) {
      t.state.method = m.method;
      t.state.subdiv_n = m.subdiv_n;
    }
  }
  if (!filter.empty()) {
    const Filter f = parse_filter(filter);
    for (ScreenTri& t : screen.tris) t.state.filter = f;
  }
}

// --config's configuration from its base one (model_config's or the rtl engine's rtl_config's):
// icebreaker-board is `icebreaker` with the board GPU's methods only (AFFINE, RECIP_LUT), which the
// rtl engine draws on that GPU, the design gpu_icebreaker_up5k synthesises.
template <class BaseConfig>
ModelConfig named_config(const std::string& name, BaseConfig base_config) {
  const bool board = name == kIcebreakerBoard;
  ModelConfig config = base_config(board ? std::string("icebreaker") : name);
  if (board) config = icebreaker_board_config(config);
  return config;
}

// The model's configuration of --config's name (QUADRATIC included; the rtl engine's is
// named_config(name, rtl_config)).
inline ModelConfig named_config(const std::string& name) {
  return named_config(name, [](const std::string& n) { return model_config(n); });
}

}  // namespace htx
