#include "htx/render/pipeline.h"

#include "htx/hal/raster.h"
#include "htx/render/auto_method.h"

namespace htx::render {

namespace {

void to_clip(const VertexTransform& vt, const MeshVertex& in, ClipVert* out) {
  const Vec4 p = apply(vt, in.x, in.y, in.z);
  out->x = p.x;
  out->y = p.y;
  out->z = p.z;
  out->w = p.w;
  out->s = in.s;
  out->t = in.t;
  const uint32_t c = in.rgba;
  out->c[0] = static_cast<int32_t>(c & 0xFFu) << kFracBits;
  out->c[1] = static_cast<int32_t>((c >> 8) & 0xFFu) << kFracBits;
  out->c[2] = static_cast<int32_t>((c >> 16) & 0xFFu) << kFracBits;
  out->c[3] = static_cast<int32_t>(c >> 24) << kFracBits;
}

void emit_to_fifo(void*, uint32_t state_word, const uint32_t* words) { hal::raster_push_triangle(state_word, words); }

// The texture's last mip level: log2 of its larger side.
uint8_t texture_top_level(TexSize tex) { return tex.log2_width > tex.log2_height ? tex.log2_width : tex.log2_height; }

AutoMesh mesh_auto(const FrameParams& frame, const Mesh& mesh) {
  // An untextured triangle has no texel error: any method will do, so the cheapest (or RECIP_NR
  // where choosing would not pay, as for any triangle).
  const fw::AutoNum tolerance = auto_tolerance(mesh.state.textured ? frame.auto_tolerance : int64_t{1} << 40);
  return auto_mesh(frame.auto_config, {mesh.state.filter, texture_top_level(mesh.tex)}, mesh.tex, tolerance,
                   frame.methods_built);
}

// Culls, chooses the method (with `mesh_auto`, found once a mesh, for AUTO), encodes and emits one
// screen triangle.
void finish_triangle(const FrameParams& frame, const AutoMesh& mesh_auto, const Mesh& mesh,
                     const ScreenVert* const v[3], const TriangleSink& sink, DrawStats* st) {
  const int64_t area2 = screen_area2(*v[0], *v[1], *v[2]);
  if (area2 == 0) {
    ++st->degenerate;
    return;
  }
  if (frame.cull_backfaces && area2 > 0) {
    ++st->culled;
    return;
  }
  TriState state = mesh.state;
  if (state.method == kMethodAuto) {
    const fw::AutoChoice c = auto_method(v, mesh_auto);
    st->auto_skipped += c.skipped;
    state.method = c.method;
    state.subdiv_n = c.subdiv_n;
  }
  // DIVFREE has no subdivision length: its SUBDIV_N field carries the texture's last mip level, the
  // top of its per-span level choice under bilinear and trilinear filtering (docs/raster.md).
  if (state.method == kMethodDivFree) state.subdiv_n = state.textured ? texture_top_level(mesh.tex) : 0;
  fw::TriangleRecord rec;
  if (encode_triangle_fx(frame.format, v, mesh.tex, &rec) != fw::kEncodeOk) {
    ++st->encode_errors;
    return;
  }
  uint32_t words[fw::kTriangleWords];
  fw::pack_triangle(rec, words);
  sink.emit(sink.context, pack_state_word(state, state.method), words);
  ++st->sent;
}

}  // namespace

TriangleSink raster_fifo_sink() { return TriangleSink{emit_to_fifo, nullptr}; }

int mesh_position_bits(const MeshVertex* vertices, uint32_t count) {
  static_assert(sizeof(MeshVertex) % 4 == 0, "positions are read as a word stride");
  if (count == 0) return 0;
  return position_int_bits(&vertices[0].x, count, sizeof(MeshVertex) / 4);
}

void process_vertices(const VertexTransform& vt, const MeshVertex* vertices, uint32_t count, const Viewport& vp,
                      VertexCache* cache) {
  for (uint32_t i = 0; i < count; ++i) {
    ClipVert& c = cache->clip[i];
    to_clip(vt, vertices[i], &c);
    const uint32_t code = outcode(c);
    cache->outcode[i] = static_cast<uint8_t>(code);
    if (code == 0) project(c, vp, &cache->screen[i]);
  }
}

DrawStatus draw_mesh(const FrameParams& frame, const Mat4& view_proj, const Mesh& mesh, VertexCache* cache,
                     const TriangleSink& sink, DrawStats* st) {
  const Viewport& vp = frame.viewport;
  if (vp.width < 1 || vp.width > 4096 || vp.height < 1 || vp.height > 4096) return kDrawBadViewport;
  if (mesh.vertex_count > cache->capacity) return kDrawCacheTooSmall;
  for (uint32_t i = 0; i < 3 * mesh.triangle_count; ++i)
    if (mesh.indices[i] >= mesh.vertex_count) return kDrawBadIndex;
  if (mesh.position_bits < 0 || mesh.position_bits > 14) return kDrawBadPositions;
  const VertexTransform vt = make_mesh_transform(view_proj, mesh.model, mesh.position_bits);
  process_vertices(vt, mesh.vertices, mesh.vertex_count, vp, cache);

  const AutoMesh auto_of_mesh = mesh.state.method == kMethodAuto ? mesh_auto(frame, mesh) : AutoMesh{};
  for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
    ++st->triangles;
    const uint16_t* idx = mesh.indices + 3 * t;
    const uint32_t c0 = cache->outcode[idx[0]], c1 = cache->outcode[idx[1]], c2 = cache->outcode[idx[2]];
    if (c0 & c1 & c2) {
      ++st->rejected;
      continue;
    }
    if ((c0 | c1 | c2) == 0) {
      const ScreenVert* v[3] = {&cache->screen[idx[0]], &cache->screen[idx[1]], &cache->screen[idx[2]]};
      finish_triangle(frame, auto_of_mesh, mesh, v, sink, st);
      continue;
    }
    ++st->clipped;
    ClipPolygon poly;
    poly.count = 3;
    for (int k = 0; k < 3; ++k) poly.v[k] = cache->clip[idx[k]];
    if (clip_polygon(&poly, (c0 | c1 | c2) & kOutcodePlanes) == kClipTooManyVertices) ++st->clip_dropped;
    if (poly.count == 0) continue;
    ScreenVert screen[kMaxClipVerts];
    for (int k = 0; k < poly.count; ++k) project(poly.v[k], vp, &screen[k]);
    for (int k = 1; k + 1 < poly.count; ++k) {
      const ScreenVert* v[3] = {&screen[0], &screen[k], &screen[k + 1]};
      finish_triangle(frame, auto_of_mesh, mesh, v, sink, st);
    }
  }
  return kDrawOk;
}

}  // namespace htx::render
