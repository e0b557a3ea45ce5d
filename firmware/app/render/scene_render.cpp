#include "scene_render.hpp"

#include <stdio.h>

#include "frame_crc.hpp"
#include "htx/hal/texture.h"
#include "htx/hal/timer.h"
#include "htx/render/frame.h"
#include "render_state.hpp"
#include "soc_config.hpp"

namespace render_app {

namespace {

constexpr uint32_t kMaxVertices = kMaxMeshVertices;
constexpr uint32_t kMaxPolls = 20'000'000;  // far beyond any frame of these scenes

htx::render::ClipVert g_clip[kMaxVertices];
htx::render::ScreenVert g_screen[kMaxVertices];
uint8_t g_codes[kMaxVertices];

// CPU cycles and vertex count of the geometry stage over every mesh of a scene, kGeometryRuns times.
void time_geometry(const SceneData& sc, const htx::render::Viewport& vp, htx::render::VertexCache* cache,
                   DrawResult* r) {
  for (uint32_t m = 0; m < sc.mesh_count; ++m) {
    const htx::render::Mesh& mesh = sc.meshes[m];
    const htx::render::VertexTransform vt =
        htx::render::make_mesh_transform(sc.view_proj, mesh.model, mesh.position_bits);
    htx::render::process_vertices(vt, mesh.vertices, mesh.vertex_count, vp, cache);  // warm up
    const uint64_t t0 = htx::hal::cpu_cycles();
    for (uint32_t run = 0; run < kGeometryRuns; ++run)
      htx::render::process_vertices(vt, mesh.vertices, mesh.vertex_count, vp, cache);
    r->geometry_cycles += htx::hal::cpu_cycles() - t0;
    r->geometry_vertices += uint64_t{kGeometryRuns} * mesh.vertex_count;
  }
}

// The meshes as drawn: the scene's own with the render state set for the draw, so that the scene
// itself stays as it is (a setting for one draw does not stay in the next).
htx::render::Mesh g_draw_meshes[kMaxSceneMeshes];

}  // namespace

void print_ratio(uint64_t num, uint64_t den) {
  const uint64_t hundredths = den ? (num * 100 + den / 2) / den : 0;
  printf("%lu.%02lu", static_cast<unsigned long>(hundredths / 100), static_cast<unsigned long>(hundredths % 100));
}

void print_raster_figures(const htx::hal::RasterCounters& c) {
  if (c.built) {
    printf("raster_cycles %lu fragments %lu", static_cast<unsigned long>(c.busy),
           static_cast<unsigned long>(c.fragments));
  } else {
    fputs("raster_cycles - fragments -", stdout);
  }
}

DrawResult draw_scene(const SceneData& sc, const DrawSettings& settings) {
  DrawResult r;
  htx::render::FrameParams frame;
  if (const char* why = plan_draw(sc, settings, htx::hal::raster_caps().methods, htx::hal::texture_caps().filters,
                                  g_draw_meshes, &frame)) {
    r.error = why;
    return r;
  }
  htx::render::VertexCache cache{g_clip, g_screen, g_codes, kMaxVertices};
  if (settings.time_geometry) time_geometry(sc, frame.viewport, &cache, &r);

  htx::render::DrawStatus mesh_status = htx::render::kDrawOk;
  htx::hal::raster_clear_state_error();
  htx::hal::texture_clear_errors();
  const uint64_t f0 = htx::hal::cpu_cycles();
  const htx::render::FrameStatus st = htx::render::render_frame(
      frame, {kClearColor, kClearDepth, settings.clear}, sc.view_proj, g_draw_meshes, sc.mesh_count, &cache, kMaxPolls, &r.stats,
      &mesh_status);
  r.frame_cycles = htx::hal::cpu_cycles() - f0;
  if (st != htx::render::kFrameOk) {
    r.error = "render_frame failed";
    return r;
  }
  if (htx::hal::raster_state_error()) {
    r.error = "the raster unit reports a state error";
    return r;
  }
  // A format or filter the unit does not build samples as 0: plan_draw refuses both, so this is
  // the hardware disagreeing with its CAPS.
  if (htx::hal::texture_errors()) {
    r.error = "the texture unit reports a format or filter error";
    return r;
  }
  htx::hal::raster_read_counters(&r.counters);
  if (settings.checksum) r.crc = frame_crc32(kWidth, kHeight);
  r.ok = true;
  return r;
}

}  // namespace render_app
