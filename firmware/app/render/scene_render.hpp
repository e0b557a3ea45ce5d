// Drawing one compiled-in scene on the SoC's GPU with the firmware render pipeline, and what it
// cost: shared by the render firmware (which prints it) and the console (`render SCENE`).
#pragma once

#include <stdint.h>

#include "htx/hal/raster.h"
#include "htx/render/pipeline.h"
#include "htx/render/scene_pack.h"
#include "htx/render/texture_pack.h"
#include "scenes.hpp"
#include "soc_texture.hpp"

namespace render_app {

// DrawSettings::filter: each mesh keeps the filter its scene gives it.
inline constexpr uint8_t kSceneFilter = 0xFF;
// The most meshes draw_scene draws in one scene (the console's uploads hold as many).
inline constexpr uint32_t kMaxSceneMeshes = htx::render::kConsoleSceneMeshes;

// A texture slot as draw_scene sees it (slot 0: soc_texture.hpp's checkerboard by default).
struct SlotTexture {
  uint8_t log2_width = 0, log2_height = 0;
  bool present = false;
};
inline constexpr uint32_t kDrawTextureSlots = htx::render::kConsoleTextureSlots;

struct DrawSettings {
  uint8_t method = htx::render::kMethodAuto;  // every triangle's method (AUTO: the firmware picks)
  uint8_t subdiv_n = 16;                      // for SUBDIV
  uint8_t filter = kSceneFilter;              // every textured triangle's filter (0 nearest, 1 bilinear,
                                              // 2 trilinear), or each mesh's own
  int64_t auto_tolerance = 0;                 // AUTO's tolerance, Q16.16 texels (0: soc_config's)
  bool time_geometry = true;                  // also time the geometry stage alone (kGeometryRuns runs)
  bool checksum = true;                       // compute the frame's CRC-32 (DrawResult::crc; about 0.8 M cycles)
  bool clear = true;                          // false: draw over the frame there (colour and depth)
  // The texture in each slot (its size scales the meshes' texture coordinates). A compiled-in
  // scene draws with slot 0; an uploaded one (SceneData::own_shading) with each mesh's own slot,
  // or slot 0 when that slot holds no texture.
  SlotTexture textures[kDrawTextureSlots] = {{kTextureLog2, kTextureLog2, true}};
};

inline constexpr uint32_t kGeometryRuns = 4;
// The vertex cache's size: the most vertices a mesh may have (floor has 81).
inline constexpr uint32_t kMaxMeshVertices = htx::render::kMaxPackedMeshVertices;

struct DrawResult {
  bool ok = false;
  const char* error = "";                     // why not, when !ok
  htx::render::DrawStats stats;
  uint64_t geometry_cycles = 0, geometry_vertices = 0;  // over kGeometryRuns runs
  uint64_t frame_cycles = 0;                  // CPU cycles of render_frame
  htx::hal::RasterCounters counters;          // the raster unit's, after the frame
  uint32_t crc = 0;                           // frame_crc32 of the colour window (0 without checksum)
};

// Applies the SoC render state (render_state.hpp) with `settings` to the scene's meshes and draws it.
DrawResult draw_scene(const SceneData& scene, const DrawSettings& settings);

// What draw_scene draws, found without the GPU: the scene's meshes with the SoC render state and
// `settings` applied (into `meshes`, room for kMaxSceneMeshes) and the frame's parameters, for a GPU
// that builds `methods_built` (RASTER CAPS.METHODS) and `filters_built` (TEXTURE CAPS.FILTERS).
// Returns nullptr, or why the scene cannot be drawn. The host runs the same plan through the
// pipeline into the model (the texel errors of a console's frame, docs/metrics.md).
const char* plan_draw(const SceneData& scene, const DrawSettings& settings, uint32_t methods_built,
                      uint32_t filters_built, htx::render::Mesh* meshes, htx::render::FrameParams* frame);

// x.xx without floating point.
void print_ratio(uint64_t num, uint64_t den);

// The report lines' "raster_cycles R fragments G" (CNT_BUSY, CNT_FRAGMENTS), each `-` when the
// unit has no counters (the board's build; CAPS.COUNTERS = 0).
void print_raster_figures(const htx::hal::RasterCounters& c);

}  // namespace render_app
