#include "scene_store.hpp"

#include "htx/render/scene_pack.h"
#include "scene_render.hpp"

namespace console_app {

namespace {

// Words, for the alignment the packed vertices need when they are read in place.
uint32_t g_bytes[2][kStoreBytes / 4];
htx::render::Mesh g_meshes[2][kStoreMeshes];
render_app::SceneData g_scene[2];
uint32_t g_size[2];
int g_committed = -1;  // index of the committed buffer; the other one receives

int staging_index() { return g_committed == 0 ? 1 : 0; }

}  // namespace

uint8_t* staging_bytes() { return reinterpret_cast<uint8_t*>(g_bytes[staging_index()]); }

const char* commit_staged(uint32_t size) {
  const int s = staging_index();
  if (size > kStoreBytes) return "larger than the scene store";
  htx::render::UnpackedScene u;
  const char* why = htx::render::unpack_scene(reinterpret_cast<const uint8_t*>(g_bytes[s]), size, g_meshes[s],
                                              kStoreMeshes, render_app::kMaxMeshVertices, &u);
  if (why) return why;
  g_scene[s] = {"upload", g_meshes[s], u.mesh_count, u.view_proj, u.cull_backfaces, true};
  g_size[s] = size;
  g_committed = s;
  return nullptr;
}

const render_app::SceneData* uploaded_scene() { return g_committed < 0 ? nullptr : &g_scene[g_committed]; }

uint32_t uploaded_size() { return g_committed < 0 ? 0 : g_size[g_committed]; }

}  // namespace console_app
