// Render firmware: uploads its checkerboard texture with the mip chain (soc_texture.hpp), then draws
// the compiled-in built-in scenes (`floor`, then `cube`; an image may select fewer,
// scene_selection.hpp) textured on the SoC's GPU with the firmware render pipeline (firmware/render
// over hal/target) and reports, one line per scene on the UART:
//   render <scene> vertices <n> geometry_cycles_per_vertex <c.cc> triangles <t> sent <s> dropped <d>
//     clipped <k> culled <u> auto_skipped <a> frame_cycles <f> raster_cycles <r> fragments <g>
//     crc32 <8 hex digits>
// dropped: triangles the vertex-record encoder refused (outside the record format's ranges) or the
// clipper could not hold (a triangle a few ulps across; htx::render::kClipTooManyVertices).
// geometry_cycles_per_vertex: CPU cycles of process_vertices (transform, clip test, projection) per
// vertex, the mean of kGeometryRuns runs after a warm-up. auto_skipped: AUTO's choices taken as
// RECIP_NR without comparing, where choosing would not pay (docs/auto.md). frame_cycles: CPU cycles of the whole frame
// (clear, geometry, streaming, waiting for the raster unit). raster_cycles and fragments: the raster
// unit's CNT_BUSY and CNT_FRAGMENTS, `-` on a build without counters (CAPS.COUNTERS). crc32:
// frame_crc.hpp over the colour window. Exits 0, or 1 on any failure.
#include <stdint.h>
#include <stdio.h>

#include "scene_render.hpp"
#include "scene_selection.hpp"
#include "scenes.hpp"
#include "soc_texture.hpp"

namespace {

constexpr uint32_t kMaxPolls = 20'000'000;
uint32_t g_texture_image[render_app::kTextureTexels];

bool render_scene(const render_app::SceneData& sc) {
  const render_app::DrawResult r = render_app::draw_scene(sc, {});
  if (!r.ok) {
    printf("render %s: %s\n", sc.name, r.error);
    return false;
  }
  printf("render %s vertices %lu geometry_cycles_per_vertex ", sc.name,
         static_cast<unsigned long>(r.geometry_vertices / render_app::kGeometryRuns));
  render_app::print_ratio(r.geometry_cycles, r.geometry_vertices);
  printf(" triangles %lu sent %lu dropped %lu clipped %lu culled %lu auto_skipped %lu frame_cycles %lu ",
         static_cast<unsigned long>(r.stats.triangles), static_cast<unsigned long>(r.stats.sent),
         static_cast<unsigned long>(r.stats.dropped()),
         static_cast<unsigned long>(r.stats.clipped), static_cast<unsigned long>(r.stats.culled),
         static_cast<unsigned long>(r.stats.auto_skipped), static_cast<unsigned long>(r.frame_cycles));
  render_app::print_raster_figures(r.counters);
  printf(" crc32 %08lx\n", static_cast<unsigned long>(r.crc));
  return true;
}

}  // namespace

int main() {
  const htx::render::UploadStatus up = render_app::upload_scene_texture(kMaxPolls, g_texture_image);
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
