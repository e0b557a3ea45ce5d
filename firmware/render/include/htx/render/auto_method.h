// AUTO in the pipeline: a screen triangle of the fixed-point geometry stage handed to the shared
// chooser (htx/fw/auto_select.h, docs/auto.md): the cheapest perspective method whose predicted
// texel error bound is within the frame's tolerance.
#pragma once

#include <stdint.h>

#include "htx/fw/auto_select.h"
#include "htx/render/encode.h"
#include "htx/render/project.h"

namespace htx::render {

// The chooser's view of a screen triangle: pixels, w, level-0 texels (u = s * 2^log2_width), exact.
fw::AutoTriangleNum auto_triangle(const ScreenVert* const v[3], TexSize tex);

// A tolerance in Q16.16 texels (> 0) as the chooser takes it (beyond 2^15 texels, as good as any).
fw::AutoNum auto_tolerance(int64_t tol_q16);

// What AUTO takes from a mesh and its frame, the same for each of the mesh's triangles.
struct AutoMesh {
  fw::AutoPricing pricing;  // the raster unit's
  fw::AutoSampling sampling;
  fw::AutoNum tolerance;  // auto_tolerance's
  uint32_t built = 0;     // bit i: method i built by the raster unit
  TexSize tex{};
  // The chooser's first rule (RECIP_NR where choosing does not pay), tested in integers on the
  // fixed-point vertices before any AutoNum work, with a margin: a triangle that passes is one the
  // chooser would skip; near the limits the chooser itself decides (docs/auto.md).
  uint32_t skip_gain16 = 0;                       // fw::pixel_gain16 of the configuration
  int64_t skip_area_limit = 0;                    // (|area2| + slack) * skip_gain16 below it; 0: never
  int64_t skip_s_range = -1, skip_t_range = -1;   // ranges of s and t (Q16.16) at most these
};
AutoMesh auto_mesh(const fw::AutoConfig& cfg, fw::AutoSampling sampling, TexSize tex, fw::AutoNum tolerance,
                   uint32_t built);

// The choice for one triangle of the mesh: fw::choose_method's, bit for bit (its bound and cycles
// are left 0 where the integer test above takes RECIP_NR).
fw::AutoChoice auto_method(const ScreenVert* const v[3], const AutoMesh& mesh);

}  // namespace htx::render
