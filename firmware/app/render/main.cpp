// Render firmware: uploads its checkerboard texture with the mip chain (soc_texture.hpp), then draws
// the compiled-in built-in scenes (`floor`, then `cube`; an image may select fewer,
// scene_selection.hpp) textured on the SoC's GPU with the firmware render pipeline (firmware/render
// over hal/target) and reports, one line per scene on the UART:
//   render <scene> vertices <n> geometry_cycles_per_vertex <c.cc> triangles <t> sent <s> clipped <k>
//     culled <u> frame_cycles <f> raster_cycles <r> fragments <g> crc32 <8 hex digits>
// geometry_cycles_per_vertex: CPU cycles of process_vertices (transform, clip test, projection) per
// vertex, the mean of kRuns runs after a warm-up. frame_cycles: CPU cycles of the whole frame
// (clear, geometry, streaming, waiting for the raster unit). raster_cycles: the raster unit's
// CNT_BUSY. crc32: frame_crc.hpp over the colour window. Exits 0, or 1 on any failure.
#include <stdint.h>
#include <stdio.h>

#include "frame_crc.hpp"
#include "htx/hal/raster.h"
#include "htx/hal/timer.h"
#include "htx/render/frame.h"
#include "htx/render/pipeline.h"
#include "render_state.hpp"
#include "scene_selection.hpp"
#include "scenes.hpp"
#include "soc_config.hpp"
#include "soc_texture.hpp"

namespace {

constexpr uint32_t kRuns = 4;
constexpr uint32_t kMaxVertices = 128;
constexpr uint32_t kMaxPolls = 20'000'000;  // far beyond any frame of these scenes

htx::render::ClipVert g_clip[kMaxVertices];
htx::render::ScreenVert g_screen[kMaxVertices];
uint8_t g_codes[kMaxVertices];

// x.xx without floating point.
void print_ratio(uint64_t num, uint64_t den) {
  const uint64_t hundredths = den ? (num * 100 + den / 2) / den : 0;
  printf("%lu.%02lu", static_cast<unsigned long>(hundredths / 100), static_cast<unsigned long>(hundredths % 100));
}

// CPU cycles and vertex count of the geometry stage over every mesh of a scene, kRuns times.
void time_geometry(const render_app::SceneData& sc, const htx::render::Viewport& vp, htx::render::VertexCache* cache,
                   uint64_t* cycles, uint64_t* vertices) {
  *cycles = 0;
  *vertices = 0;
  for (uint32_t m = 0; m < sc.mesh_count; ++m) {
    const htx::render::Mesh& mesh = sc.meshes[m];
    const htx::render::VertexTransform vt =
        htx::render::make_vertex_transform(htx::render::mat4_mul(sc.view_proj, mesh.model), mesh.position_bits);
    htx::render::process_vertices(vt, mesh.vertices, mesh.vertex_count, vp, cache);  // warm up
    const uint64_t t0 = htx::hal::cpu_cycles();
    for (uint32_t r = 0; r < kRuns; ++r)
      htx::render::process_vertices(vt, mesh.vertices, mesh.vertex_count, vp, cache);
    *cycles += htx::hal::cpu_cycles() - t0;
    *vertices += uint64_t{kRuns} * mesh.vertex_count;
  }
}

bool render_scene(const render_app::SceneData& sc) {
  for (uint32_t m = 0; m < sc.mesh_count; ++m) {
    if (sc.meshes[m].vertex_count > kMaxVertices) {
      printf("render %s: mesh %lu has %lu vertices, more than %lu\n", sc.name, static_cast<unsigned long>(m),
             static_cast<unsigned long>(sc.meshes[m].vertex_count), static_cast<unsigned long>(kMaxVertices));
      return false;
    }
    render_app::apply_soc_render_state(&sc.meshes[m]);
  }
  htx::render::VertexCache cache{g_clip, g_screen, g_codes, kMaxVertices};
  htx::render::FrameParams frame;
  frame.viewport = {render_app::kWidth, render_app::kHeight};
  frame.format = render_app::kRecordFormat;
  frame.methods_built = render_app::kMethodsBuilt;
  frame.auto_config = render_app::kAutoConfig;
  frame.auto_tolerance = render_app::kAutoTolerance;
  frame.cull_backfaces = sc.cull_backfaces;

  uint64_t geo_cycles = 0, geo_vertices = 0;
  time_geometry(sc, frame.viewport, &cache, &geo_cycles, &geo_vertices);

  htx::render::DrawStats stats;
  htx::render::DrawStatus mesh_status = htx::render::kDrawOk;
  htx::hal::raster_clear_state_error();
  const uint64_t f0 = htx::hal::cpu_cycles();
  const htx::render::FrameStatus st =
      htx::render::render_frame(frame, {render_app::kClearColor, render_app::kClearDepth}, sc.view_proj, sc.meshes,
                                sc.mesh_count, &cache, kMaxPolls, &stats, &mesh_status);
  const uint64_t frame_cycles = htx::hal::cpu_cycles() - f0;
  if (st != htx::render::kFrameOk) {
    printf("render %s: render_frame failed with status %d (mesh status %d)\n", sc.name, st, mesh_status);
    return false;
  }
  if (htx::hal::raster_state_error()) {
    printf("render %s: the raster unit reports a state error\n", sc.name);
    return false;
  }
  htx::hal::RasterCounters counters;
  htx::hal::raster_read_counters(&counters);
  const uint32_t crc = render_app::frame_crc32(render_app::kWidth, render_app::kHeight);

  printf("render %s vertices %lu geometry_cycles_per_vertex ", sc.name,
         static_cast<unsigned long>(geo_vertices / kRuns));
  print_ratio(geo_cycles, geo_vertices);
  printf(" triangles %lu sent %lu clipped %lu culled %lu frame_cycles %lu raster_cycles %lu fragments %lu crc32 %08lx\n",
         static_cast<unsigned long>(stats.triangles), static_cast<unsigned long>(stats.sent),
         static_cast<unsigned long>(stats.clipped), static_cast<unsigned long>(stats.culled),
         static_cast<unsigned long>(frame_cycles), static_cast<unsigned long>(counters.busy),
         static_cast<unsigned long>(counters.fragments), static_cast<unsigned long>(crc));
  return true;
}

}  // namespace

int main() {
  const htx::render::UploadStatus up = render_app::upload_scene_texture(kMaxPolls);
  if (up != htx::render::kUploadOk) {
    printf("render: texture upload failed with status %d\n", up);
    return 1;
  }
  uint32_t n = 0;
  const render_app::SceneData* scenes = render_app::builtin_scenes(&n);
  for (uint32_t s = 0; s < n; ++s)
    if (render_app::draw_scene_named(scenes[s].name) && !render_scene(scenes[s])) return 1;
  return 0;
}
