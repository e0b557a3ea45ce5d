// Geometry benchmark: CPU cycles per vertex of the firmware geometry stage (transform, clip test,
// and projection of the vertices inside the frustum: htx::render::process_vertices) over the
// vertices of the built-in `cube` and `floor` scenes, and cycles per triangle of the whole pipeline
// (draw_mesh without a raster unit: clipping, culling, AUTO, encoding), from the cycle CSR:
//   geombench <scene> vertices <n> projected <p> cycles/vertex <c.cc>
//   geombench <scene> triangles <n> sent <s> cycles/triangle <c>
//   geombench <scene> triangles <n> sent <s> cycles/triangle <c> method recip_nr
//   geombench <scene> triangles <n> sent <s> cycles/triangle <c> auto soc skipped <k>
//   geombench <scene> triangles <n> sent <s> cycles/triangle <c> method recip_nr soc
// (the second the same pipeline with every triangle's method fixed, so the difference is AUTO's
// choice: its bounds and costs, htx/fw/auto_select.h; the first with the default `full`
// configuration, which never skips a choice, at 1/64 texel and 320 x 240; the third AUTO as the
// SoC's render firmware draws: `icebreaker`'s configuration, 1/16 texel, 160 x 120, k choices
// skipped where they would not pay, docs/auto.md; the fourth the same with the method fixed)
//   geombench all vertices <n> cycles/vertex <c.cc>
// and, for each triangle sent, what its setup costs the firmware for the `icebreaker` raster unit,
// which takes plane records (CAPS.FW_SETUP; htx/fw/plane_record.h, docs/raster.md "Plane record"):
// the plane record as the HAL makes it (coverage, 1/det, the edges and the planes, AFFINE's
// vertex divisions, DIVFREE's side band) for a 160 x 120 screen, without the FIFO writes:
//   geombench <scene> setup triangles <s> records <r> words <w> cycles/triangle <c>
#include <stdint.h>
#include <stdio.h>

#include "htx/fw/plane_record.h"
#include "htx/fw/vertex_record.h"
#include "htx/hal/raster.h"
#include "htx/hal/timer.h"
#include "htx_regs.h"
#include "htx/render/pipeline.h"
#include "scenes.hpp"

namespace {

constexpr uint32_t kRuns = 8;
constexpr uint32_t kMaxVertices = 81;

htx::render::ClipVert g_clip[kMaxVertices];
htx::render::ScreenVert g_screen[kMaxVertices];
uint8_t g_codes[kMaxVertices];

void count_triangle(void* context, uint32_t, const uint32_t*) { ++*static_cast<uint32_t*>(context); }

// The plane record of each triangle sent, timed on its own, as the HAL makes it for the
// `icebreaker` raster unit (htx::hal::raster_plane_job: its parameters and table) on a 160 x 120
// screen with texture mapping built.
constexpr uint32_t kSetupFbSize = 160u | (120u << RASTER_FB_SIZE_HEIGHT_Pos);
constexpr uint32_t kSetupCaps = RASTER_CAPS_METHODS_Msk | RASTER_CAPS_FW_SETUP_Msk;

struct SetupTally {
  uint32_t triangles = 0, records = 0, words = 0;
  uint64_t cycles = 0;
  uint32_t checksum = 0;  // keeps the results live
};

void time_setup(void* context, uint32_t state_word, const uint32_t* words) {
  SetupTally& t = *static_cast<SetupTally*>(context);
  htx::fw::TriangleRecord rec;
  htx::fw::unpack_triangle(words, &rec);
  const htx::fw::PlaneJob job = htx::hal::raster_plane_job(state_word, kSetupFbSize, kSetupCaps);
  uint32_t out[htx::fw::kPlaneRecordMaxWords];
  size_t n = 0;
  const uint64_t t0 = htx::hal::cpu_cycles();
  const htx::fw::PlaneStatus status = htx::fw::encode_plane_record(job, rec, out, &n);
  t.cycles += htx::hal::cpu_cycles() - t0;
  ++t.triangles;
  t.records += status == htx::fw::kPlaneOk;
  t.words += static_cast<uint32_t>(n);
  for (size_t i = 0; i < n; ++i) t.checksum = (t.checksum << 1 | t.checksum >> 31) ^ out[i];
}

// x.xx without floating point.
void print_ratio(uint64_t num, uint64_t den) {
  const uint64_t hundredths = (num * 100 + den / 2) / den;
  printf("%lu.%02lu", static_cast<unsigned long>(hundredths / 100), static_cast<unsigned long>(hundredths % 100));
}

// draw_mesh without a raster unit, timed; prints the failure and returns false if it fails.
bool timed_draw(const htx::render::FrameParams& frame, const geombench::BenchScene& sc, const htx::render::Mesh& mesh,
                htx::render::VertexCache* cache, uint32_t* sent, htx::render::DrawStats* st, uint64_t* cycles) {
  const uint64_t t0 = htx::hal::cpu_cycles();
  const htx::render::DrawStatus status = htx::render::draw_mesh(frame, sc.view_proj, mesh, cache, {count_triangle, sent}, st);
  *cycles = htx::hal::cpu_cycles() - t0;
  if (status != htx::render::kDrawOk) {
    printf("geombench %s: draw_mesh (method %u) failed with status %d\n", sc.name, mesh.state.method, status);
    return false;
  }
  return true;
}

// timed_draw, then the line's common part, "geombench <scene> triangles <n> sent <s> cycles/triangle
// <c>"; the caller ends the line.
bool print_timed_draw(const htx::render::FrameParams& frame, const geombench::BenchScene& sc,
                      const htx::render::Mesh& mesh, htx::render::VertexCache* cache, htx::render::DrawStats* st) {
  uint32_t sent = 0;
  uint64_t cycles = 0;
  if (!timed_draw(frame, sc, mesh, cache, &sent, st, &cycles)) return false;
  printf("geombench %s triangles %lu sent %lu cycles/triangle %lu", sc.name, static_cast<unsigned long>(sc.triangle_count),
         static_cast<unsigned long>(sent), static_cast<unsigned long>(cycles / sc.triangle_count));
  return true;
}

}  // namespace

int main() {
  htx::hal::raster_fw_setup_params();  // fills the reciprocal table once, outside the timing
  uint32_t n = 0;
  const geombench::BenchScene* scenes = geombench::bench_scenes(&n);
  htx::render::VertexCache cache{g_clip, g_screen, g_codes, kMaxVertices};
  const htx::render::Viewport vp{320, 240};
  uint64_t all_cycles = 0, all_vertices = 0;
  for (uint32_t s = 0; s < n; ++s) {
    const geombench::BenchScene& sc = scenes[s];
    const int bits = htx::render::mesh_position_bits(sc.vertices, sc.vertex_count);
    const htx::render::VertexTransform vt =
        htx::render::make_mesh_transform(sc.view_proj, sc.model, bits);
    htx::render::process_vertices(vt, sc.vertices, sc.vertex_count, vp, &cache);  // warm up
    const uint64_t t0 = htx::hal::cpu_cycles();
    for (uint32_t r = 0; r < kRuns; ++r) htx::render::process_vertices(vt, sc.vertices, sc.vertex_count, vp, &cache);
    const uint64_t cycles = htx::hal::cpu_cycles() - t0;
    uint32_t projected = 0;
    for (uint32_t i = 0; i < sc.vertex_count; ++i) projected += g_codes[i] == 0;
    const uint64_t verts = uint64_t{kRuns} * sc.vertex_count;
    printf("geombench %s vertices %lu projected %lu cycles/vertex ", sc.name, static_cast<unsigned long>(sc.vertex_count),
           static_cast<unsigned long>(projected));
    print_ratio(cycles, verts);
    printf("\n");
    all_cycles += cycles;
    all_vertices += verts;

    htx::render::Mesh mesh{sc.vertices, sc.vertex_count, sc.indices, sc.triangle_count, sc.model, {}, {6, 6},
                           static_cast<int8_t>(bits)};
    mesh.state.method = htx::render::kMethodAuto;
    htx::render::FrameParams frame;
    frame.viewport = vp;
    htx::render::DrawStats st;
    uint32_t sent = 0;
    uint64_t dc = 0;
    if (!timed_draw(frame, sc, mesh, &cache, &sent, &st, &dc)) return 1;
    printf("geombench %s triangles %lu sent %lu clipped %lu cycles/triangle %lu\n", sc.name,
           static_cast<unsigned long>(sc.triangle_count), static_cast<unsigned long>(sent),
           static_cast<unsigned long>(st.clipped), static_cast<unsigned long>(dc / sc.triangle_count));

    htx::render::Mesh fixed = mesh;
    fixed.state.method = htx::render::kMethodRecipNr;
    if (!print_timed_draw(frame, sc, fixed, &cache, &st)) return 1;
    printf(" method recip_nr\n");

    htx::render::FrameParams soc_frame;
    soc_frame.viewport = {160, 120};
    soc_frame.auto_config = htx::fw::kAutoConfigIcebreaker;
    soc_frame.auto_tolerance = htx::render::kOne / 16;
    htx::render::DrawStats soc_st;
    if (!print_timed_draw(soc_frame, sc, mesh, &cache, &soc_st)) return 1;
    printf(" auto soc skipped %lu\n", static_cast<unsigned long>(soc_st.auto_skipped));
    if (!print_timed_draw(soc_frame, sc, fixed, &cache, &soc_st)) return 1;
    printf(" method recip_nr soc\n");

    SetupTally tally;
    if (htx::render::draw_mesh(frame, sc.view_proj, mesh, &cache, {time_setup, &tally}, &st) == htx::render::kDrawOk &&
        tally.triangles != 0) {
      printf("geombench %s setup triangles %lu records %lu words %lu cycles/triangle %lu (checksum %08lx)\n", sc.name,
             static_cast<unsigned long>(tally.triangles), static_cast<unsigned long>(tally.records),
             static_cast<unsigned long>(tally.words), static_cast<unsigned long>(tally.cycles / tally.triangles),
             static_cast<unsigned long>(tally.checksum));
    }
  }
  printf("geombench all vertices %lu cycles/vertex ", static_cast<unsigned long>(all_vertices));
  print_ratio(all_cycles, all_vertices);
  printf("\n");
  return 0;
}
