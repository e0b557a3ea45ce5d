// The uploaded scene (docs/console.md, "Scene upload"): two buffers, the committed scene and the
// one being received. A received scene replaces the committed one only once it is complete and
// unpack_scene (htx/render/scene_pack.h) has found it valid; until then the committed one stays
// as it was.
#pragma once

#include <stdint.h>

#include "scene_render.hpp"
#include "scenes.hpp"

namespace console_app {

// Per buffer: randmesh's 7,248 bytes fit; tunnel's 62,520 do not (two buffers that size would fill
// the 128 KiB RAM): htx sends it in parts, each drawn over the last.
inline constexpr uint32_t kStoreBytes = htx::render::kConsoleSceneBytes;
// Meshes of a scene: htx upload splits larger meshes into parts of at most kMaxMeshVertices.
inline constexpr uint32_t kStoreMeshes = render_app::kMaxSceneMeshes;

// Where a scene or texture is received (kStoreBytes, 4-byte aligned); at boot, before anything
// arrives, the scratch image of the checkerboard's upload (soc_texture.hpp).
uint8_t* staging_bytes();

// Checks the `size` received bytes and, if they are a valid scene, makes them the committed scene.
// Returns nullptr, or what is wrong (the committed scene is then unchanged).
const char* commit_staged(uint32_t size);

// The committed scene, named "upload"; nullptr before the first successful upload.
const render_app::SceneData* uploaded_scene();
uint32_t uploaded_size();

}  // namespace console_app
