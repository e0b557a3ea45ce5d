// Texture sampling for the reference renderer: the stored texels, decoded, filtered in double.
#pragma once

#include <array>

#include "htx/model/types.hpp"

namespace htx::ref {

using Rgba = std::array<double, 4>;  // [0, 1]

struct Sample {
  Rgba color{};
  int level = 0;  // sampled level (the finer one for trilinear)
};

// u, v in texels of level 0; lod as computed by the caller. Nearest and bilinear read level 0,
// trilinear blends floor(lod) and floor(lod) + 1 (level 0 bilinear when lod <= 0, the last level when
// lod reaches it).
Sample sample_texture(const Texture& tex, Filter filter, Wrap wrap_u, Wrap wrap_v, double u, double v,
                      double lod);

}  // namespace htx::ref
