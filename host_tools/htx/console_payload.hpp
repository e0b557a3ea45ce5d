// What htx upload sends to the console firmware (docs/console.md, "Scene upload", "Texture
// upload"): a scene in the firmware's packed form with its texture, or an image as a texture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "htx/model/scene.hpp"
#include "htx/render/scene_pack.h"
#include "htx/render/texture_pack.h"

namespace htx {

// A scene's packed form (htx/render/scene_pack.h), its meshes split into parts of at most
// mesh_vertices vertices (host::split_meshes), and, unless with_texture is false, its textures
// packed (htx/render/texture_pack.h), one per console texture slot: the textures its textured
// meshes use, in the order of first use, each as its largest mip level of at most
// render::kConsoleTextureTexels texels with sides of 8 or more; each mesh names its texture's slot.
// A texture past the console's render::kConsoleTextureSlots, or with no level it takes, is not
// sent, and its meshes name slot 0. `untextured`: every mesh marked untextured, and no texture.
// `note` says what was done with the meshes and the textures when it is worth saying.
// `parts`: the same meshes packed as scenes of at most render::kConsoleSceneBytes bytes and
// render::kConsoleSceneMeshes meshes each, in order (one part, equal to `scene`, when it fits), for
// drawing one over the other (`render upload over`); each has the whole scene's camera.
struct ScenePayload {
  std::vector<uint8_t> scene;
  std::vector<std::vector<uint8_t>> parts;
  std::vector<std::vector<uint8_t>> textures;  // [slot]; an empty one is not sent
  std::vector<int> slot_of_texture;            // [scene texture index]: the slot its meshes name
  std::vector<uint32_t> source_mesh;           // [packed mesh, over the parts in order]: its Scene mesh
  std::string note;
};
ScenePayload scene_payload(const std::string& spec, const std::string& size, bool with_texture,
                           uint32_t mesh_vertices = render::kMaxPackedMeshVertices, bool untextured = false);
// The same for a scene already loaded from `spec` (which names it in errors).
ScenePayload scene_payload(const Scene& scene, const std::string& spec, const std::string& size, bool with_texture,
                           uint32_t mesh_vertices = render::kMaxPackedMeshVertices, bool untextured = false);

// An image as the console's texture: sides powers of two in 8..256, each pixel encoded in
// `format_name` (rgb565 or rgba4444), the image's bottom row as texel row 0 (v = 0), as the model
// reads an OBJ's texture. Throws std::invalid_argument on a bad size or format.
std::vector<uint8_t> packed_texture(const std::string& path, const std::string& format_name);

}  // namespace htx
