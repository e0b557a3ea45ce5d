// draw_scene's plan (scene_render.hpp): the meshes as drawn and the frame's parameters, without
// touching the GPU, so that the host can run the same plan into the model.
#include "scene_render.hpp"

#include "render_state.hpp"
#include "soc_config.hpp"

namespace render_app {

const char* plan_draw(const SceneData& sc, const DrawSettings& settings, uint32_t methods_built,
                      uint32_t filters_built, htx::render::Mesh* meshes, htx::render::FrameParams* frame) {
  if (settings.method != htx::render::kMethodAuto && !((methods_built >> settings.method) & 1u))
    return "this GPU does not build that perspective method (CAPS.METHODS)";
  if (sc.mesh_count > kMaxSceneMeshes) return "the scene has more meshes than draw_scene draws";
  for (uint32_t m = 0; m < sc.mesh_count; ++m) {
    if (sc.meshes[m].vertex_count > kMaxMeshVertices) return "a mesh has more vertices than the vertex cache";
    htx::render::Mesh& mesh = meshes[m];
    mesh = sc.meshes[m];
    apply_soc_render_state(&mesh);
    uint32_t slot = kTextureSlot;
    if (sc.own_shading) {
      mesh.state.textured = sc.meshes[m].state.textured;
      mesh.state.gouraud = sc.meshes[m].state.gouraud;
      slot = sc.meshes[m].state.texture;
    }
    if (slot >= kDrawTextureSlots || !settings.textures[slot].present) slot = kTextureSlot;
    if (mesh.state.textured && !settings.textures[slot].present)
      return "a textured mesh's texture slot and slot 0 hold no texture (upload one)";
    mesh.state.texture = static_cast<uint8_t>(slot);
    mesh.tex = {settings.textures[slot].log2_width, settings.textures[slot].log2_height};
    mesh.state.method = settings.method;
    mesh.state.subdiv_n = settings.subdiv_n;
    if (settings.filter != kSceneFilter) mesh.state.filter = settings.filter;
    // A filter the texture unit lacks would be sampled bilinear at level 0 (TEXTURE ERR_FILTER)
    // without a word, so a textured mesh that asks for one is refused before anything is drawn
    // (an untextured one samples nothing).
    const uint8_t filter = mesh.state.filter;
    if (mesh.state.textured && (filter > 2 || !((filters_built >> filter) & 1u)))
      return "a mesh's filter is one this GPU does not build (TEXTURE CAPS.FILTERS; `set filter` another)";
  }
  *frame = htx::render::FrameParams{};
  frame->viewport = {kWidth, kHeight};
  frame->format = kRecordFormat;
  // The simulated SoC builds every method, the board AFFINE and RECIP_LUT: AUTO picks among these.
  frame->methods_built = methods_built;
  frame->auto_config = kAutoConfig;
  frame->auto_tolerance = settings.auto_tolerance > 0 ? settings.auto_tolerance : kAutoTolerance;
  frame->cull_backfaces = sc.cull_backfaces;
  return nullptr;
}

}  // namespace render_app
