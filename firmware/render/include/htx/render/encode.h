// The fixed-point vertex-record encoder: the same record as htx::fw::encode_triangle
// (firmware/lib vertex_record.h) from fixed-point inputs, without floating point (the double
// encoder is too slow on the soft CPU). Differences to the double encoder are bounded
// (docs/firmware.md, "Vertex records").
#pragma once

#include <stdint.h>

#include "htx/fw/vertex_record.h"
#include "htx/render/project.h"

namespace htx::render {

// Texture size of the triangle (u = s * 2^log2_width texels, v = t * 2^log2_height); 0 for an
// untextured triangle is fine (u, v are still encoded, and ignored by the raster unit).
struct TexSize {
  uint8_t log2_width = 0, log2_height = 0;
};

// Encodes one triangle. Status values are htx::fw's: kEncodeBadFormat for a width outside its
// range, kEncodeBadW for w <= 0, kEncodeXyRange for x or y outside +-2^(xy_int_bits-1) pixels,
// kEncodeUvRange when u - u_offset or v - v_offset needs more than min(uv_int_bits, 16) integer
// bits or an offset reaches 2^30. On an error *out is not usable and the triangle must not be sent.
fw::EncodeStatus encode_triangle_fx(const fw::RecordFormat& format, const ScreenVert* const v[3], TexSize tex,
                                    fw::TriangleRecord* out);

}  // namespace htx::render
