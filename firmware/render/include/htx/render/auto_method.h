// AUTO: per triangle, the cheapest perspective method whose predicted texel error is within the
// scene's tolerance (docs/firmware.md, "AUTO"; the model's htx::model::auto_method uses the same
// bound in doubles). The affine error of a triangle is bounded by
//   E = du * (sqrt(r) - 1) / (sqrt(r) + 1),  r = w_max / w_min,
// du = the largest difference of u or of v between its vertices (texels). E <= tol is evaluated
// without square roots or division: with a = du - tol, b = du + tol it is du <= tol or
// a^2 * w_max <= b^2 * w_min.
#pragma once

#include <stdint.h>

#include "htx/render/project.h"

namespace htx::render {

// Predicted affine error within tolerance? du and tol in Q16.16 texels (du >= 0, tol > 0), w in
// Q16.16 (> 0). Exact when du + tol < 2^16 (one texel); otherwise a and b keep their top 16 bits.
bool affine_within(int64_t du, int64_t tol, int32_t w_min, int32_t w_max);

// The method for a triangle asking for AUTO: AFFINE if built and within tolerance, else the most
// accurate divider built (RECIP_NR, else RECIP_LUT, else SUBDIV). `built`: bit i = method i.
uint8_t auto_method(const ScreenVert* const v[3], uint8_t log2_width, uint8_t log2_height, int64_t tol,
                    uint32_t built);

}  // namespace htx::render
