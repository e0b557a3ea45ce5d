// The geometry pipeline of the firmware: per vertex transform, clip test and projection; per
// triangle trivial reject, clipping, back-face culling, the AUTO method choice, the vertex-record
// encoder and streaming of the triangle (state word + record words) to a sink. No heap: the caller
// provides the per-vertex cache.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "htx/fw/auto_select.h"
#include "htx/fw/vertex_record.h"
#include "htx/render/clip.h"
#include "htx/render/encode.h"
#include "htx/render/project.h"
#include "htx/render/transform.h"
#include "htx/render/tri_state.h"
#include "htx/render/vertex_transform.h"

namespace htx::render {

struct MeshVertex {
  int32_t x, y, z;  // object space, Q16.16
  int32_t s, t;     // normalised texture coordinates, Q16.16 (1.0 = one texture width)
  uint32_t rgba;    // r in bits 7:0, g 15:8, b 23:16, a 31:24
};

struct Mesh {
  const MeshVertex* vertices;
  uint32_t vertex_count;
  const uint16_t* indices;  // three per triangle
  uint32_t triangle_count;
  Mat4 model;               // object -> world
  TriState state;           // state.method may be kMethodAuto
  TexSize tex;              // size of state.texture (u = s * width)
  int8_t position_bits;     // integer bits of the largest |coordinate| (mesh_position_bits)
};

// The integer bits (0..14) the largest coordinate of a mesh needs; computed once per mesh. Positions
// must stay below 2^14 in magnitude.
int mesh_position_bits(const MeshVertex* vertices, uint32_t count);

struct FrameParams {
  Viewport viewport;
  fw::RecordFormat format;
  uint32_t methods_built = 0x1F;           // bit i = method i built by the raster unit
  int64_t auto_tolerance = kOne / 64;      // AUTO: largest predicted texel error, Q16.16 texels
  fw::AutoConfig auto_config{};            // AUTO: the raster configuration's bounds and costs (full)
  bool cull_backfaces = true;              // front faces are counter-clockwise in NDC
};

// Per-vertex results of one mesh; arrays of `capacity` entries owned by the caller.
struct VertexCache {
  ClipVert* clip;
  ScreenVert* screen;  // valid where outcode is 0
  uint8_t* outcode;
  uint32_t capacity;
};

// Where finished triangles go: the state word and the kTriangleWords record words.
struct TriangleSink {
  void (*emit)(void* context, uint32_t state_word, const uint32_t* words);
  void* context;
};

// A sink that streams into the raster unit's FIFO through the HAL.
TriangleSink raster_fifo_sink();

struct DrawStats {
  uint32_t triangles = 0;     // triangles of the meshes
  uint32_t rejected = 0;      // entirely outside one plane
  uint32_t clipped = 0;       // crossed a plane and went through the clipper
  uint32_t culled = 0;        // back-facing
  uint32_t degenerate = 0;    // zero area on the subpixel grid
  uint32_t encode_errors = 0; // the encoder refused them (not sent)
  uint32_t clip_dropped = 0;  // clipped to more vertices than a polygon holds (a few ulps across)
  uint32_t sent = 0;          // triangles streamed (after clipping, a fan counts per triangle)
  uint32_t auto_skipped = 0;  // AUTO's: RECIP_NR without comparing, where choosing would not pay
  // Triangles not sent for what they are (the render lines' `dropped`): refused or not held.
  uint32_t dropped() const { return encode_errors + clip_dropped; }
};

enum DrawStatus : int {
  kDrawOk = 0,
  kDrawCacheTooSmall = 1,  // vertex_count > cache capacity: nothing drawn
  kDrawBadIndex = 2,       // an index >= vertex_count: nothing drawn
  kDrawBadViewport = 3,    // a viewport side outside 1..4096: nothing drawn
  kDrawBadPositions = 4,   // position_bits outside 0..14: nothing drawn
};

// Per vertex: clip = mvp * (x, y, z, 1), the outcode, and the projection when the vertex is inside
// every plane. The stage the geometry benchmark times.
void process_vertices(const VertexTransform& vt, const MeshVertex* vertices, uint32_t count, const Viewport& vp,
                      VertexCache* cache);

// Draws a mesh with view_proj = projection * view. Triangles go to `sink` in mesh order (a clipped
// triangle as the fan poly[0], poly[k], poly[k+1]), the same order as the host geometry stage.
DrawStatus draw_mesh(const FrameParams& frame, const Mat4& view_proj, const Mesh& mesh, VertexCache* cache,
                     const TriangleSink& sink, DrawStats* stats);

}  // namespace htx::render
