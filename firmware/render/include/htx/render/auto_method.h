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

// pricing: the raster unit's fw::auto_pricing; tol: auto_tolerance's; built: bit i = method i built
// by the raster unit. All but the triangle are a mesh's: the pipeline finds them once a mesh.
fw::AutoChoice auto_method(const ScreenVert* const v[3], TexSize tex, const fw::AutoPricing& pricing,
                           const fw::AutoSampling& sampling, fw::AutoNum tol, uint32_t built);

}  // namespace htx::render
