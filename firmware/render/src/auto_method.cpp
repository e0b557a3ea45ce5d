#include "htx/render/auto_method.h"

namespace htx::render {

fw::AutoTriangle auto_triangle(const ScreenVert* const v[3], TexSize tex) {
  fw::AutoTriangle t;
  const float to_px = 1.0f / 256.0f, to_unit = 1.0f / 65536.0f;
  const float width = static_cast<float>(1u << tex.log2_width), height = static_cast<float>(1u << tex.log2_height);
  for (int i = 0; i < 3; ++i) {
    t.x[i] = static_cast<float>(v[i]->x) * to_px;
    t.y[i] = static_cast<float>(v[i]->y) * to_px;
    t.w[i] = static_cast<float>(v[i]->w) * to_unit;
    t.u[i] = static_cast<float>(v[i]->attr->s) * to_unit * width;
    t.v[i] = static_cast<float>(v[i]->attr->t) * to_unit * height;
  }
  return t;
}

fw::AutoChoice auto_method(const ScreenVert* const v[3], TexSize tex, const fw::AutoConfig& cfg,
                           const fw::AutoSampling& sampling, int64_t tol, uint32_t built) {
  return fw::choose_method(auto_triangle(v, tex), cfg, sampling, built,
                           static_cast<float>(tol) * (1.0f / 65536.0f));
}

}  // namespace htx::render
