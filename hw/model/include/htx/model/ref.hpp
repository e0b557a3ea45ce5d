// The `ref` engine: a float64 renderer with no fixed point anywhere. Ground truth for every metric.
//
// Coverage is exact (exact orientation predicates, pixel centres at +0.5, top-left rule); z is
// interpolated linearly in screen space (window z is affine there), u, v and colour perspective-
// correctly (u/w, v/w, colour/w and 1/w linear, one division per pixel); the LOD is log2 of the
// longer of the two derivative vectors (du/dx, dv/dx), (du/dy, dv/dy), computed analytically.
// Texture sampling reads the stored texels (texture.hpp decode) and filters in double.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/model/types.hpp"

namespace htx {

struct RefOptions {
  // Width of the stored depth values in Frame::depth (the test itself runs on doubles) and of the
  // clear depth (ScreenScene::clear_depth is clipped to it).
  unsigned depth_bits = 24;
};

Frame render_ref(const ScreenScene& scene, const RefOptions& options = {});

// Number of triangles covering each pixel centre (row-major), ignoring depth and state: the fill-rule
// check (a closed mesh's silhouette must be covered exactly once).
std::vector<uint32_t> ref_coverage_count(const ScreenScene& scene);

// Nearest-texel index along one axis for a coordinate in texels of the sampled level, OpenGL texel
// convention with exact ties to the lower index: ceil(c) - 1 (before wrapping).
long long ref_nearest_index(double c);

}  // namespace htx
