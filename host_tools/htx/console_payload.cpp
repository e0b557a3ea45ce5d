#include "console_payload.hpp"

#include <algorithm>
#include <stdexcept>

#include "frame_size.hpp"
#include "htx/fw/mip_chain.h"
#include "htx/fw/texel.h"
#include "htx/host/render_scene.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/obj_loader.hpp"
#include "htx/model/scenes.hpp"
#include "htx/render/scene_pack.h"
#include "htx/render/texture_pack.h"

namespace htx {

namespace {

// Level `level` of `t` packed as 16-bit texels (RGBA8888 re-encoded as RGB565).
std::vector<uint8_t> pack_level(const Texture& t, unsigned level) {
  const unsigned lw = fw::mip_level_log2(t.log2_width, level), lh = fw::mip_level_log2(t.log2_height, level);
  const bool wide = t.format == TexFormat::RGBA8888;
  const uint8_t format = static_cast<uint8_t>(wide ? TexFormat::RGB565 : t.format);
  std::vector<uint16_t> texels(t.levels[level].size());
  for (size_t k = 0; k < texels.size(); ++k)
    texels[k] = static_cast<uint16_t>(
        wide ? fw::encode_texel(format, fw::decode_texel(fw::kTexelRgba8888, t.levels[level][k])) : t.levels[level][k]);
  std::vector<uint8_t> packed(render::packed_texture_size(lw, lh));
  if (render::pack_texture(static_cast<uint8_t>(lw), static_cast<uint8_t>(lh), format, texels.data(), packed.data(),
                           packed.size()) != packed.size())
    throw std::logic_error("pack_texture refused a model texture level");
  return packed;
}

// Adds a note to a "; "-separated list of them (an empty note adds nothing).
void add_note(std::string* notes, const std::string& note) {
  if (note.empty()) return;
  if (!notes->empty()) *notes += "; ";
  *notes += note;
}

// The largest mip level of `t` the console takes (at most render::kConsoleTextureTexels texels,
// sides at least 8), packed; empty with a note when none is.
std::vector<uint8_t> packed_texture_level(const Texture& t, std::string* note) {
  const uint32_t max_texels = render::kConsoleTextureTexels;
  unsigned level = 0, lw = t.log2_width, lh = t.log2_height;
  while ((1u << (lw + lh)) > max_texels && lw > 3 && lh > 3 && level + 1 < t.levels.size()) {
    ++level;
    --lw;
    --lh;
  }
  const std::string size0 = std::to_string(1u << t.log2_width) + "x" + std::to_string(1u << t.log2_height);
  if ((1u << (lw + lh)) > max_texels) {
    *note = "the scene's " + size0 + " texture has no mip level of at most " + std::to_string(max_texels) +
            " texels with sides of 8 or more; not sent";
    return {};
  }
  if (level > 0)
    *note = "the scene's " + size0 + " texture sent as its " + std::to_string(1u << lw) + "x" +
            std::to_string(1u << lh) + " mip level (the console takes at most " + std::to_string(max_texels) +
            " texels)";
  if (t.format == TexFormat::RGBA8888) add_note(note, "RGBA8888 sent as RGB565");
  return pack_level(t, level);
}

// The textures the scene's textured meshes use, in the order they first use them, packed for
// console slots 0, 1, ... (at most render::kConsoleTextureSlots; one with no level the console
// takes leaves its slot empty); (*slot_of)[index] is the slot of scene texture `index`, 0 for a
// texture not sent. The texture index is the Scene mesh's: render::TriState's is a byte, in
// which texture 256 would read as 0.
std::vector<std::vector<uint8_t>> textures_in_slots(const Scene& scene, const host::RenderScene& rs,
                                                    std::vector<int>* slot_of, std::string* note) {
  std::vector<int> used;
  for (const host::RenderScene::MeshData& d : rs.meshes) {
    const int texture = scene.meshes[d.source].state.texture;
    if (d.mesh.state.textured && std::find(used.begin(), used.end(), texture) == used.end())
      used.push_back(texture);
  }
  std::vector<std::vector<uint8_t>> textures;
  for (size_t slot = 0; slot < used.size() && slot < render::kConsoleTextureSlots; ++slot) {
    const size_t index = static_cast<size_t>(used[slot]);
    if (index >= scene.textures.size()) continue;
    std::string level_note;
    std::vector<uint8_t> packed = packed_texture_level(scene.textures[index], &level_note);
    if (packed.empty()) {
      add_note(note, level_note);
      continue;
    }
    if (!level_note.empty())
      add_note(note, (used.size() > 1 ? "texture " + std::to_string(slot) + ": " : "") + level_note);
    (*slot_of)[index] = static_cast<int>(slot);
    textures.resize(slot + 1);
    textures[slot] = std::move(packed);
  }
  if (used.size() > render::kConsoleTextureSlots)
    add_note(note, "the scene uses " + std::to_string(used.size()) + " textures and the console keeps " +
                       std::to_string(render::kConsoleTextureSlots) + "; the meshes of the others draw with texture 0");
  return textures;
}

// The meshes, in order, packed as scenes of at most render::kConsoleSceneBytes bytes and
// render::kConsoleSceneMeshes meshes (a single mesh larger than that is a part of its own, which
// the console refuses), each with the whole scene's camera.
std::vector<std::vector<uint8_t>> scene_parts(const host::RenderScene& rs, const std::vector<render::Mesh>& meshes) {
  std::vector<std::vector<uint8_t>> parts;
  for (size_t first = 0; first < meshes.size();) {
    size_t end = first + 1;
    while (end < meshes.size() && end - first < render::kConsoleSceneMeshes &&
           render::packed_scene_size(&meshes[first], static_cast<uint32_t>(end + 1 - first)) <=
               render::kConsoleSceneBytes)
      ++end;
    const uint32_t n = static_cast<uint32_t>(end - first);
    std::vector<uint8_t> part(render::packed_scene_size(&meshes[first], n));
    if (render::pack_scene(rs.view_proj, rs.cull_backfaces, &meshes[first], n, part.data(), part.size()) == 0)
      throw std::logic_error("pack_scene refused a part of a scene it packed whole");
    parts.push_back(std::move(part));
    first = end;
  }
  return parts;
}

}  // namespace

ScenePayload scene_payload(const std::string& spec, const std::string& size, bool with_texture,
                           uint32_t mesh_vertices, bool untextured) {
  return scene_payload(load_scene(spec), spec, size, with_texture, mesh_vertices, untextured);
}

ScenePayload scene_payload(const Scene& scene, const std::string& spec, const std::string& size, bool with_texture,
                           uint32_t mesh_vertices, bool untextured) {
  int width = 0, height = 0;
  parse_size(size, width, height);
  // The firmware's form of the scene (as the render firmware's compiled-in scenes are made), packed.
  host::RenderScene rs;
  try {
    rs = host::to_render_scene(scene, width, height, /*keep_wide=*/true);  // split_meshes narrows
  } catch (const std::out_of_range& e) {
    throw std::invalid_argument("'" + spec + "' cannot go to the console: " + e.what());
  }
  // A mesh without triangles draws nothing, and the console refuses one (an empty mesh is what a
  // damaged upload looks like), so it is not sent; a scene with none at all cannot be.
  std::erase_if(rs.meshes,
                [](const host::RenderScene::MeshData& d) { return d.indices.empty() && d.wide_indices.empty(); });
  if (rs.meshes.empty()) throw std::invalid_argument("'" + spec + "' has no triangles to send to the console");
  const size_t whole_meshes = rs.meshes.size();
  host::split_meshes(&rs, mesh_vertices);
  ScenePayload p;
  for (const std::string& n : scene.notes) add_note(&p.note, n);
  if (rs.meshes.size() != whole_meshes)
    add_note(&p.note, std::to_string(whole_meshes) + " meshes sent as " + std::to_string(rs.meshes.size()) +
                          " of at most " + std::to_string(mesh_vertices) + " vertices");
  std::string texture_note;
  std::vector<int> slot_of(scene.textures.size(), 0);  // scene texture index -> console slot
  if (with_texture && !untextured) p.textures = textures_in_slots(scene, rs, &slot_of, &texture_note);
  p.slot_of_texture = slot_of;

  std::vector<render::Mesh> meshes;
  for (const host::RenderScene::MeshData& d : rs.meshes) {
    meshes.push_back(d.mesh);
    p.source_mesh.push_back(d.source);
    if (untextured) meshes.back().state.textured = false;
    const size_t texture = static_cast<size_t>(scene.meshes[d.source].state.texture);
    meshes.back().state.texture = static_cast<uint8_t>(texture < slot_of.size() ? slot_of[texture] : 0);
  }
  const uint32_t count = static_cast<uint32_t>(meshes.size());
  p.scene.resize(render::packed_scene_size(meshes.data(), count));
  if (render::pack_scene(rs.view_proj, rs.cull_backfaces, meshes.data(), count, p.scene.data(), p.scene.size()) == 0)
    throw std::runtime_error("'" + spec +
                             "' does not fit the packed scene format (65535 vertices or triangles a mesh)");
  // (One part, the scene itself, when it fits one upload.)
  p.parts = p.scene.size() <= render::kConsoleSceneBytes && count <= render::kConsoleSceneMeshes
                ? std::vector<std::vector<uint8_t>>{p.scene}
                : scene_parts(rs, meshes);
  if (p.parts.size() > 1)
    add_note(&p.note, "the packed scene is " + std::to_string(p.scene.size()) +
                          " bytes, more than the console's store holds (" +
                          std::to_string(render::kConsoleSceneBytes) + "): `htx render --engine soc|board` draws it in " +
                          std::to_string(p.parts.size()) + " parts, each over the last");
  add_note(&p.note, texture_note);
  return p;
}

std::vector<uint8_t> packed_texture(const std::string& path, const std::string& format_name) {
  TexFormat format = TexFormat::RGB565;
  if (format_name == "rgba4444")
    format = TexFormat::RGBA4444;
  else if (format_name != "rgb565")
    throw std::invalid_argument("--format must be rgb565 or rgba4444, not '" + format_name + "'");
  const Image img = load_image(path);
  // Refused here, before the port is opened, rather than by the console after the transfer.
  if (static_cast<uint64_t>(img.width) * static_cast<uint64_t>(img.height) > render::kConsoleTextureTexels)
    throw std::invalid_argument("'" + path + "' is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                                ": a console texture slot holds at most " +
                                std::to_string(render::kConsoleTextureTexels) + " texels (e.g. 32x32)");
  try {
    return pack_level(texture_from_image(img, path, format), 0);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // the sides: a usage error, as for the other arguments
  }
}

}  // namespace htx
