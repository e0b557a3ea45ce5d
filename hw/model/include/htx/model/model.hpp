// The bit-accurate fixed-point model of the raster and texture units (engine `model`): the
// executable specification the RTL matches bit for bit. docs/model.md is its written form.
//
// Conventions shared with the reference engine:
// - Vertices are encoded into vertex records (x, y on a 1/256-pixel grid, see vertex_record.h).
// - Coverage: pixel centres at +0.5, top-left fill rule, both windings drawn (back faces are culled
//   by the geometry stage); zero-area triangles and triangles the encoder rejects draw nothing.
// - Texel addressing: u in level-0 texels (u = s * width); at level L the coordinate is u / 2^L.
//   Nearest picks texel ceil(uL) - 1 (texel i covers (i, i+1]; exact ties go to the lower index
//   on both axes). Bilinear samples around uL - 0.5 with 8-bit weights.
// - Nearest and bilinear sample level 0; trilinear blends levels floor(lod) and floor(lod)+1.
#pragma once

#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/types.hpp"

namespace htx {

// A screen vertex as the vertex-record encoder takes it (the firmware's VertexIn, in doubles).
fw::VertexIn to_vertex_in(const ScreenVertex& v);

// Renders a screen scene. Per-triangle TriState selects method, filter, wrap, depth and combine.
// Throws std::invalid_argument when a triangle asks for a method, filter or texture format the
// configuration does not build, names a missing texture, or the scene size is outside 1..4096.
Frame render_model(const ScreenScene& scene, const ModelConfig& config);

// A triangle as the firmware streams it: its vertex record and its state, method resolved.
struct RecordTriangle {
  fw::TriangleRecord record;
  TriState state;
  int mesh = 0;  // the scene mesh it comes from (PixelProbe::mesh)
};

// Triangles given as vertex records (e.g. what the firmware streamed), in drawing order.
struct RecordScene {
  int width = 320, height = 240;
  std::vector<Texture> textures;
  std::vector<RecordTriangle> tris;
  uint16_t clear_color = 0;
  uint32_t clear_depth = 0xFFFFFFFFu;
};

// The model from the vertex records on (render_model without its encoder and AUTO): the frame for
// records the firmware produced. Throws std::invalid_argument like render_model, and for a record
// whose method is Auto.
Frame render_model_records(const RecordScene& scene, const ModelConfig& config);

}  // namespace htx
