// The built-in `cube` and `floor` scenes (hw/model/src/scene/builtin) compiled into the render
// firmware, in the firmware pipeline's formats: Q16.16 meshes and the fixed-point camera matrix.
// The data (scene_data.cpp) is generated from the model's scenes by tests/system/render_scene_dump;
// the system test SystemRender.CompiledInScenesEqualTheModelsScenes checks it field by field.
#pragma once

#include <stdint.h>

#include "htx/render/pipeline.h"

namespace render_app {

struct SceneData {
  const char* name;
  const htx::render::Mesh* meshes;  // as the scene gives them (draw_scene sets the render state on copies)
  uint32_t mesh_count;
  htx::render::Mat4 view_proj;  // projection * view, for the screen's 4:3 aspect
  bool cull_backfaces;
  // Its meshes keep their own textured and Gouraud flags (an uploaded scene); the compiled-in
  // scenes are drawn textured and Gouraud-shaded (render_state.hpp).
  bool own_shading = false;
};

// The scenes in drawing order (the last one stays in the framebuffer at exit).
const SceneData* builtin_scenes(uint32_t* count);

}  // namespace render_app
