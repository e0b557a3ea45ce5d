// AUTO: per triangle, the cheapest perspective method whose predicted texel-coordinate error bound
// is within a tolerance (docs/auto.md has the bounds, their derivation and the cost model). Shared by
// the firmware pipeline (firmware/render, fixed-point vertices converted here) and the host
// (`htx render --method auto --tolerance T`), so both pick with the same code.
//
// The interface is float; inside, a floating-point type of integer operations (htx/fw/auto_num.h):
// the bounds need products of screen and texture quantities whose ranges do not fit a fixed-point
// format, the host and the rv32im CPU must give identical choices, and on the CPU the soft-float
// library cost about 37,000 cycles a triangle (docs/auto.md, "Arithmetic"). Reported bounds and
// costs are rounded up to float. Freestanding C++17.
#pragma once

#include <stdint.h>

#include "htx/fw/auto_num.h"

namespace htx::fw {

// Method numbers of the RASTER STATE word (and of htx::Method).
enum AutoMethod : uint8_t {
  kAutoAffine = 0,
  kAutoSubdiv = 1,
  kAutoRecipLut = 2,
  kAutoRecipNr = 3,
  kAutoDivFree = 4,
};

// The fields of a raster configuration the bounds and costs depend on (names of htx::ModelConfig;
// docs/model.md's table). The defaults are `full`; kAutoConfigIcebreaker is the SoC's unit.
struct AutoConfig {
  uint8_t recip_table_bits = 10;     // k
  uint8_t recip_guard_bits = 2;      // g
  uint8_t recip_width = 32;          // W
  uint8_t pixel_nr_steps = 2;        // Newton steps of RECIP_NR and the exact points of SUBDIV
  uint8_t recip_issue_interval = 1;  // clocks between divisions of the shared reciprocal unit
  uint8_t texcoord_frac_bits = 16;   // TF
  uint8_t divfree_frac_bits = 4;     // f
  // The cost model (docs/auto.md), in sixteenths of a raster clock: traversal clocks per pixel,
  // clocks per division of RECIP_LUT and of RECIP_NR (SUBDIV's exact points are RECIP_NR divisions),
  // and AFFINE's extra setup per triangle (its vertex divisions).
  uint16_t pixel_cost16 = 16;
  uint16_t lut_divide_cost16 = 16;
  uint16_t nr_divide_cost16 = 16;
  uint16_t affine_setup_cost16 = 0;
  // The CPU clocks one choice costs the system that draws (0: nothing). Where no method could save
  // the raster unit more clocks than that against RECIP_NR, AUTO takes RECIP_NR without comparing
  // (docs/auto.md, "When choosing does not pay").
  uint16_t choice_cycles = 0;
};
// The most a pixel can save the raster unit against RECIP_NR, in sixteenths of a clock: RECIP_NR's
// division less the traversal's step, or 0 where the traversal sets the pace anyway.
inline uint32_t pixel_gain16(const AutoConfig& c) {
  return c.nr_divide_cost16 > c.pixel_cost16 ? uint32_t{c.nr_divide_cost16} - c.pixel_cost16 : 0u;
}

// `full`: one pixel a clock and a division a clock, no CPU measured. `icebreaker`: measured on its
// RTL and on the SoC's CPU (docs/auto.md).
inline constexpr AutoConfig kAutoConfigFull{10, 2, 32, 2, 1, 16, 4, 16, 16, 16, 0, 0};
inline constexpr AutoConfig kAutoConfigIcebreaker{8, 2, 24, 1, 3, 10, 2, 193, 245, 373, 2560, 4500};

inline bool operator==(const AutoConfig& a, const AutoConfig& b) {
  return a.recip_table_bits == b.recip_table_bits && a.recip_guard_bits == b.recip_guard_bits &&
         a.recip_width == b.recip_width && a.pixel_nr_steps == b.pixel_nr_steps &&
         a.recip_issue_interval == b.recip_issue_interval && a.texcoord_frac_bits == b.texcoord_frac_bits &&
         a.divfree_frac_bits == b.divfree_frac_bits && a.pixel_cost16 == b.pixel_cost16 &&
         a.lut_divide_cost16 == b.lut_divide_cost16 && a.nr_divide_cost16 == b.nr_divide_cost16 &&
         a.affine_setup_cost16 == b.affine_setup_cost16 && a.choice_cycles == b.choice_cycles;
}

// Any configuration type with the ModelConfig field names (the host's htx::ModelConfig).
template <class Config>
AutoConfig auto_config_of(const Config& c) {
  AutoConfig a;
  a.recip_table_bits = static_cast<uint8_t>(c.recip_table_bits);
  a.recip_guard_bits = static_cast<uint8_t>(c.recip_guard_bits);
  a.recip_width = static_cast<uint8_t>(c.recip_width);
  a.pixel_nr_steps = static_cast<uint8_t>(c.pixel_nr_steps);
  a.recip_issue_interval = static_cast<uint8_t>(c.recip_issue_interval);
  a.texcoord_frac_bits = static_cast<uint8_t>(c.texcoord_frac_bits);
  a.divfree_frac_bits = static_cast<uint8_t>(c.divfree_frac_bits);
  a.pixel_cost16 = static_cast<uint16_t>(c.auto_pixel_cost16);
  a.lut_divide_cost16 = static_cast<uint16_t>(c.auto_lut_divide_cost16);
  a.nr_divide_cost16 = static_cast<uint16_t>(c.auto_nr_divide_cost16);
  a.affine_setup_cost16 = static_cast<uint16_t>(c.auto_affine_setup_cost16);
  a.choice_cycles = static_cast<uint16_t>(c.auto_choice_cycles);
  return a;
}

// A screen triangle: x, y in pixels, clip w (> 0, any common unit), u, v in level-0 texels.
struct AutoTriangle {
  float x[3], y[3], w[3], u[3], v[3];
};
// The same in AutoNum, which the firmware builds from its fixed-point vertices without float.
struct AutoTriangleNum {
  AutoNum x[3], y[3], w[3], u[3], v[3];
};

// What the triangle is drawn with (texture filter and the texture's last mip level, for DIVFREE's
// cell size).
struct AutoSampling {
  uint8_t filter = 1;     // 0 nearest, 1 bilinear, 2 trilinear
  uint8_t top_level = 0;  // max(log2 width, log2 height) of the texture
};

struct AutoChoice {
  uint8_t method = kAutoRecipNr;
  uint8_t subdiv_n = 16;  // for kAutoSubdiv (2..64)
  bool within = false;    // the predicted bound is within the tolerance (else: the fallback)
  bool skipped = false;   // RECIP_NR without comparing: choosing would not pay (AutoConfig::choice_cycles)
  float bound = 0;        // predicted max texel-coordinate error of the choice (texels)
  float cycles = 0;       // predicted raster cycles of the triangle (docs/model.md §9 estimate)
};

// Predicted error bounds (texels) of each method for one triangle; bound_subdiv(n) per span length.
struct AutoBounds {
  float affine, recip_lut, recip_nr, divfree;
  float subdiv_slope;      // max |du/dx| over the triangle (texels per pixel), the larger axis
  float subdiv_curvature;  // max |d2u/dx2| over the triangle (texels per pixel^2), the larger axis
  float span_limit;        // longest possible span: the x extent in pixels, + 1
  float du;                // largest u or v difference between the vertices (texels)
};
AutoBounds auto_bounds(const AutoTriangle& t, const AutoConfig& cfg, const AutoSampling& s);
float auto_bound_subdiv(const AutoBounds& b, const AutoConfig& cfg, unsigned n);

// Predicted raster cycles (docs/model.md §9) of drawing the triangle with `method` (n for SUBDIV).
float auto_cycles(const AutoTriangle& t, const AutoConfig& cfg, uint8_t method, unsigned n);

// What the bounds and costs take from a configuration, as AutoNum: found once (the firmware: once
// a mesh) instead of once a triangle.
struct AutoPricing {
  AutoConfig cfg;
  AutoNum base;          // 4 ulps of the texel coordinate (every method's rounding)
  AutoNum table_error;   // the reciprocal table's relative error
  AutoNum newton_error;  // the same after the pixel Newton steps
  AutoNum setup;         // clocks of setup, without the one a span
  AutoNum pixel_cost, lut_divide, nr_divide, affine_setup, seed_divide;  // clocks (docs/auto.md)
  AutoNum choice;      // choice_cycles
  AutoNum pixel_gain;  // pixel_gain16 in clocks
};
AutoPricing auto_pricing(const AutoConfig& cfg);

// The largest texel span du (texels, the larger of u's and v's) for which choose_method finds
// RECIP_NR's bound within `tolerance`, a little below the exact limit (0 or less: none). The
// firmware's integer test of the skip (htx/render/auto_method.h) reads it.
AutoNum recip_nr_span_limit(const AutoPricing& pricing, AutoNum tolerance);

// The cheapest built method (bit i of `built` = method i) whose bound is within `tolerance`
// texels; among equal costs the smaller bound. When none is within it (or the triangle is
// degenerate or not finite): RECIP_NR if built, else RECIP_LUT, else SUBDIV with n = 2, else AFFINE,
// with within = false. First, where choosing would not pay (pixels * pixel_gain < choice_cycles)
// and RECIP_NR is built and within the tolerance: RECIP_NR, with skipped = true.
AutoChoice choose_method(const AutoTriangle& t, const AutoConfig& cfg, const AutoSampling& s, uint32_t built,
                         float tolerance);
// The same choice for a triangle and tolerance in AutoNum (equal to the float version's for the
// same values; a w <= 0 or a tolerance <= 0 gives the fallback).
AutoChoice choose_method(const AutoTriangleNum& t, const AutoConfig& cfg, const AutoSampling& s, uint32_t built,
                         AutoNum tolerance);
AutoChoice choose_method(const AutoTriangleNum& t, const AutoPricing& pricing, const AutoSampling& s, uint32_t built,
                         AutoNum tolerance);
// The rule applied literally, for tests: every bound found, the plain methods in their order,
// SUBDIV's n by a scan down from 64. choose_method must give the same, bit for bit, for less work.
AutoChoice choose_method_exhaustive(const AutoTriangleNum& t, const AutoConfig& cfg, const AutoSampling& s,
                                    uint32_t built, AutoNum tolerance);

}  // namespace htx::fw
