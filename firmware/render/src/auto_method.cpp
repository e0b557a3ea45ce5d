#include "htx/render/auto_method.h"

#include "htx/render/tri_state.h"

namespace htx::render {

bool affine_within(int64_t du, int64_t tol, int32_t w_min, int32_t w_max) {
  if (du <= tol) return true;
  int64_t a = du - tol, b = du + tol;
  while (b >= (int64_t{1} << 16)) {  // keep a^2 * w below 2^63
    a >>= 1;
    b >>= 1;
  }
  const uint64_t lhs = static_cast<uint64_t>(a * a) * static_cast<uint64_t>(w_max);
  const uint64_t rhs = static_cast<uint64_t>(b * b) * static_cast<uint64_t>(w_min);
  return lhs <= rhs;
}

uint8_t auto_method(const ScreenVert* const v[3], uint8_t log2_width, uint8_t log2_height, int64_t tol,
                    uint32_t built) {
  int32_t w_min = v[0]->w, w_max = v[0]->w;
  int64_t u_lo = v[0]->attr->s, u_hi = v[0]->attr->s, t_lo = v[0]->attr->t, t_hi = v[0]->attr->t;
  for (int i = 1; i < 3; ++i) {
    if (v[i]->w < w_min) w_min = v[i]->w;
    if (v[i]->w > w_max) w_max = v[i]->w;
    if (v[i]->attr->s < u_lo) u_lo = v[i]->attr->s;
    if (v[i]->attr->s > u_hi) u_hi = v[i]->attr->s;
    if (v[i]->attr->t < t_lo) t_lo = v[i]->attr->t;
    if (v[i]->attr->t > t_hi) t_hi = v[i]->attr->t;
  }
  const int64_t du = (u_hi - u_lo) << log2_width;
  const int64_t dv = (t_hi - t_lo) << log2_height;
  if ((built & (1u << kMethodAffine)) && affine_within(du > dv ? du : dv, tol, w_min, w_max)) return kMethodAffine;
  if (built & (1u << kMethodRecipNr)) return kMethodRecipNr;
  if (built & (1u << kMethodRecipLut)) return kMethodRecipLut;
  return kMethodSubdiv;
}

}  // namespace htx::render
