// The turns of `spin`: a scene turned about the vertical line through its middle, so that a scene
// away from the world's origin (`floor`) turns in place instead of swinging out of view.
#pragma once

#include <stdint.h>

#include "scenes.hpp"

namespace console_app {

struct TurnAxis {
  int32_t x, z;  // world space, Q16.16
};

// The middle of the scene's world-space bounding box in x and z (the origin for a scene without
// vertices). Every vertex is transformed once.
TurnAxis scene_turn_axis(const render_app::SceneData& scene);

// The scene turned by turn_q16 (65,536 = a whole turn; right-handed about +y) about `axis`: only its
// view-projection changes, the meshes are shared.
render_app::SceneData turned_scene(const render_app::SceneData& scene, TurnAxis axis, uint32_t turn_q16);

}  // namespace console_app
