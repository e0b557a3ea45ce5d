#include "scene_turn.hpp"

#include "htx/render/transform.h"

namespace console_app {

TurnAxis scene_turn_axis(const render_app::SceneData& scene) {
  bool any = false;
  int64_t lo_x = 0, hi_x = 0, lo_z = 0, hi_z = 0;
  for (uint32_t m = 0; m < scene.mesh_count; ++m) {
    const htx::render::Mesh& mesh = scene.meshes[m];
    for (uint32_t i = 0; i < mesh.vertex_count; ++i) {
      const htx::render::MeshVertex& v = mesh.vertices[i];
      const htx::render::Vec4 p = htx::render::transform_point(mesh.model, v.x, v.y, v.z);
      if (!any || p.x < lo_x) lo_x = p.x;
      if (!any || p.x > hi_x) hi_x = p.x;
      if (!any || p.z < lo_z) lo_z = p.z;
      if (!any || p.z > hi_z) hi_z = p.z;
      any = true;
    }
  }
  // (the halved sums of two int32 fit an int32)
  return {static_cast<int32_t>((lo_x + hi_x) / 2), static_cast<int32_t>((lo_z + hi_z) / 2)};
}

render_app::SceneData turned_scene(const render_app::SceneData& scene, TurnAxis axis, uint32_t turn_q16) {
  render_app::SceneData turned = scene;
  turned.view_proj =
      htx::render::mat4_mul(scene.view_proj, htx::render::mat4_rotation_y_about(turn_q16, axis.x, axis.z));
  return turned;
}

}  // namespace console_app
