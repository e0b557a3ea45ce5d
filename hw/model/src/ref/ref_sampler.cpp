#include "ref_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "htx/model/ref.hpp"
#include "htx/model/texture.hpp"

namespace htx::ref {

namespace {

Rgba texel(const Texture& tex, unsigned level, long long i, long long j, Wrap wrap_u, Wrap wrap_v) {
  const unsigned x = wrap_index(wrap_u, i, level_log2_width(tex, level));
  const unsigned y = wrap_index(wrap_v, j, level_log2_height(tex, level));
  const Rgba8 c = fetch_texel(tex, level, x, y);
  return {c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0};
}

Rgba nearest(const Texture& tex, unsigned level, double u, double v, Wrap wrap_u, Wrap wrap_v) {
  return texel(tex, level, ref_nearest_index(u), ref_nearest_index(v), wrap_u, wrap_v);
}

Rgba bilinear(const Texture& tex, unsigned level, double u, double v, Wrap wrap_u, Wrap wrap_v) {
  const double x = u - 0.5, y = v - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double a = x - fx, b = y - fy;
  const auto i = static_cast<long long>(fx), j = static_cast<long long>(fy);
  const Rgba t00 = texel(tex, level, i, j, wrap_u, wrap_v);
  const Rgba t10 = texel(tex, level, i + 1, j, wrap_u, wrap_v);
  const Rgba t01 = texel(tex, level, i, j + 1, wrap_u, wrap_v);
  const Rgba t11 = texel(tex, level, i + 1, j + 1, wrap_u, wrap_v);
  Rgba r;
  for (int c = 0; c < 4; ++c)
    r[c] = (1 - b) * ((1 - a) * t00[c] + a * t10[c]) + b * ((1 - a) * t01[c] + a * t11[c]);
  return r;
}

}  // namespace

Sample sample_texture(const Texture& tex, Filter filter, Wrap wrap_u, Wrap wrap_v, double u, double v,
                      double lod) {
  Sample s;
  if (filter == Filter::Nearest) {
    s.color = nearest(tex, 0, u, v, wrap_u, wrap_v);
    return s;
  }
  if (filter == Filter::Bilinear || !(lod > 0)) {
    s.color = bilinear(tex, 0, u, v, wrap_u, wrap_v);
    return s;
  }
  const int last = static_cast<int>(tex.levels.size()) - 1;
  const double fl = std::floor(lod);
  if (fl >= last) {
    s.level = last;
    const double k = std::ldexp(1.0, -last);
    s.color = bilinear(tex, static_cast<unsigned>(last), u * k, v * k, wrap_u, wrap_v);
    return s;
  }
  const int l0 = static_cast<int>(fl);
  const double f = lod - fl;
  const double k0 = std::ldexp(1.0, -l0), k1 = std::ldexp(1.0, -(l0 + 1));
  const Rgba c0 = bilinear(tex, static_cast<unsigned>(l0), u * k0, v * k0, wrap_u, wrap_v);
  const Rgba c1 = bilinear(tex, static_cast<unsigned>(l0 + 1), u * k1, v * k1, wrap_u, wrap_v);
  for (int c = 0; c < 4; ++c) s.color[c] = (1 - f) * c0[c] + f * c1[c];
  s.level = l0;
  return s;
}

}  // namespace htx::ref
