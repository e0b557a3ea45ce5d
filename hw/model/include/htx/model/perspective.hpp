// One triangle in the raster unit after setup (docs/model.md, "Setup", "Interpolation",
// "Perspective methods"): its planes, its coverage, and the texel coordinates of a span under each
// perspective method.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/lod.hpp"
#include "htx/model/raster_setup.hpp"
#include "htx/model/recip.hpp"
#include "htx/model/texture.hpp"
#include "htx/model/types.hpp"

namespace htx::model {

// Texel coordinates of one span (local: before the per-triangle texel offset), texcoord_frac_bits.
struct SpanCoords {
  std::vector<int64_t> u, v;
  std::vector<uint32_t> divfree_steps;  // u steps + v steps at each pixel (DIVFREE)
  std::vector<uint8_t> divfree_capped;  // 1 where an axis stopped at the cap
  unsigned divfree_level = 0;           // DIVFREE: mip level whose grid the span tracked on
  uint64_t cycles = 0;                  // estimated clocks of the span
};

// The grid cell DIVFREE converges to, on the grid of 2^-f texels of mip level L: with
// x = 2^f U / (Q 2^L) (cells) and P = coord_bits, the j with j <= x - 2^-(P+1) < j + 1. In the
// integer conditions of reference 004 (Q > 0):
//   N = 2^(f+P+1) U - (2^(P+1) j + 1) Q 2^L >= 0,   M = 2^(f+P+1) U - (2^(P+1) (j+1) + 1) Q 2^L < 0.
// The half-ulp offset makes the cell the one nearest sampling selects for x rounded to P fraction
// bits (round half up), i.e. for the exact quotient at the texel-coordinate precision.
int64_t divfree_exact_index(i128 num, i128 q, unsigned grid_bits, unsigned level, unsigned coord_bits);

class TriangleUnit {
 public:
  // log2_unit and top_level (the texture's last mip level) serve DIVFREE's per-span level choice
  // under trilinear filtering; without them DIVFREE tracks on level 0.
  TriangleUnit(const fw::TriangleRecord& rec, const TriState& state, const ModelConfig& cfg, int width, int height,
               const Log2Unit* log2_unit = nullptr, unsigned top_level = 0);

  bool empty() const { return setup_.empty; }
  int y_lo() const { return setup_.y_lo; }
  int y_hi() const { return setup_.y_hi; }
  bool span(int y, int* x0, int* x1) const { return row_span(setup_, y, x0, x1); }
  uint64_t setup_cycles() const { return setup_cycles_; }

  // Rows must be visited in increasing y (DIVFREE carries its grid position from span to span).
  void span_coords(int y, int x0, int x1, Method method, SpanCoords* out) const;

  uint32_t depth_at(int64_t px, int64_t py) const;
  Rgba8 color_at(int64_t px, int64_t py) const;
  Rgba8 flat_color() const;
  int32_t lod_at(const Log2Unit& unit, int64_t px, int64_t py, int64_t u, int64_t v) const;

  const TriSetup& setup() const { return setup_; }
  const Plane& q_plane() const { return q_; }
  const Plane& uq_plane() const { return uq_; }
  const Plane& vq_plane() const { return vq_; }
  unsigned divfree_grid_bits() const { return grid_bits_; }

 private:
  int64_t divide(i128 num, i128 q, const RecipParams& p) const;
  int64_t grid_coord(int64_t j, unsigned level) const;
  void span_affine(int64_t py, int x0, int x1, SpanCoords* out) const;
  void span_divide(int64_t py, int x0, int x1, const RecipParams& p, SpanCoords* out) const;
  void span_subdiv(int64_t py, int x0, int x1, bool quadratic, SpanCoords* out) const;
  void span_divfree(int64_t py, int x0, int x1, SpanCoords* out) const;

  const ModelConfig& cfg_;
  TriState state_;
  const Log2Unit* log2_ = nullptr;
  unsigned top_level_ = 0;
  TriSetup setup_;
  RecipParams setup_recip_, pixel_nr_, pixel_lut_;
  Plane z_, q_, uq_, vq_, ua_, va_;
  Plane color_[4];  // colour, or colour * q with perspective_color
  i128 lod_grad_[6] = {};  // uq x, uq y, vq x, vq y, q x, q y after the block shift
  int lod_shift_ = 0;
  uint64_t setup_cycles_ = 0;
  unsigned grid_bits_ = 0;
  // DIVFREE position carried between spans: grid indices at the previous span's first pixel, its
  // x and row, and the movement per row at fixed x and per pixel along x (cells, 16 fraction bits).
  mutable bool df_started_ = false;
  mutable unsigned df_level_ = 0;
  mutable int64_t df_ju_ = 0, df_jv_ = 0, df_x0_ = 0, df_row_ = 0;
  mutable int64_t df_row_u_ = 0, df_row_v_ = 0, df_slope_u_ = 0, df_slope_v_ = 0;
};

// AUTO: the firmware's choice for one triangle (modelled from the ScreenVertex doubles, as the
// firmware decides before encoding): AFFINE when the predicted affine error
// du_max * (sqrt(r) - 1) / (sqrt(r) + 1), r = w_max / w_min, is at most 1/64 texel, else the most
// accurate division method the configuration builds (RECIP_NR, else RECIP_LUT, else SUBDIV).
Method auto_method(const ScreenTri& tri, const ModelConfig& cfg);

}  // namespace htx::model
