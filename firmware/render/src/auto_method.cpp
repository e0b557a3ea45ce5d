#include "htx/render/auto_method.h"

namespace htx::render {

fw::AutoTriangleNum auto_triangle(const ScreenVert* const v[3], TexSize tex) {
  // Exact: every coordinate is an integer times a power of two (1/256 pixel, Q16.16 w, s and t).
  fw::AutoTriangleNum t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = fw::num_scale(fw::num_from_int(v[i]->x), -8);
    t.y[i] = fw::num_scale(fw::num_from_int(v[i]->y), -8);
    t.w[i] = fw::num_scale(fw::num_from_int(v[i]->w), -16);
    t.u[i] = fw::num_scale(fw::num_from_int(v[i]->attr->s), tex.log2_width - 16);
    t.v[i] = fw::num_scale(fw::num_from_int(v[i]->attr->t), tex.log2_height - 16);
  }
  return t;
}

fw::AutoNum auto_tolerance(int64_t tol_q16) {
  const int32_t tol32 = tol_q16 > INT32_MAX ? INT32_MAX : tol_q16 < 0 ? 0 : static_cast<int32_t>(tol_q16);
  return fw::num_scale(fw::num_from_int(tol32), -16);
}

fw::AutoChoice auto_method(const ScreenVert* const v[3], TexSize tex, const fw::AutoPricing& pricing,
                           const fw::AutoSampling& sampling, fw::AutoNum tol, uint32_t built) {
  return fw::choose_method(auto_triangle(v, tex), pricing, sampling, built, tol);
}

}  // namespace htx::render
