// Configuration of the bit-accurate model: every width, table size and which methods, filters and
// formats are built. docs/model.md explains each field; the RTL takes the same values as parameters.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "htx/fw/tri_setup.h"
#include "htx/fw/vertex_record.h"
#include "htx/model/types.hpp"

namespace htx {

struct ModelConfig {
  std::string name;

  // Vertex record (firmware/lib/include/htx/fw/vertex_record.h).
  unsigned xy_int_bits = 16;  // x, y: signed, this many integer bits incl. sign, 8 subpixel bits
  unsigned z_bits = 24;       // depth buffer and vertex z
  unsigned q_bits = 32;       // per-vertex q mantissa (largest vertex q in [2^(q_bits-1), 2^q_bits))
  unsigned uv_int_bits = 16;  // u - u_offset in texels, signed, incl. sign

  // Setup and interpolation: every plane (z, q, uq, vq, colour) steps in fixed point with this many
  // fractional bits per subpixel below the attribute's own unit (gradients and accumulators).
  unsigned grad_frac_bits = 24;

  // The shared reciprocal unit: k-bit table, g guard bits (k+g output bits after the leading one),
  // datapath mantissa width W, Newton-Raphson steps for setup (1/determinant) and for RECIP_NR.
  unsigned recip_table_bits = 10;  // k
  unsigned recip_guard_bits = 2;   // g
  unsigned recip_width = 32;       // W (input mantissa and result width)
  unsigned setup_nr_steps = 2;
  unsigned pixel_nr_steps = 2;
  // Clocks between two divisions the unit accepts (1 = fully pipelined; a shared iterative unit
  // on a small FPGA takes 1 + steps). Used by the cycle estimate.
  unsigned recip_issue_interval = 1;

  // AUTO's cost model (docs/auto.md), in sixteenths of a raster clock: traversal clocks per pixel,
  // clocks per RECIP_LUT and per RECIP_NR division (SUBDIV's exact points are RECIP_NR divisions),
  // AFFINE's extra setup per triangle. `full`'s follow from its pipeline; `icebreaker`'s are
  // measured on its RTL. The model's cycle estimate (§9) does not use them.
  unsigned auto_pixel_cost16 = 16;
  unsigned auto_lut_divide_cost16 = 16;
  unsigned auto_nr_divide_cost16 = 16;
  unsigned auto_affine_setup_cost16 = 0;
  // The CPU clocks one AUTO choice costs the firmware (0: none); where no method could save the
  // raster unit more, AUTO takes RECIP_NR without comparing (docs/auto.md).
  unsigned auto_choice_cycles = 0;

  // Texel coordinates leave the divider as signed fixed point with this many fractional bits.
  unsigned texcoord_frac_bits = 16;

  // DIVFREE: grid of 2^-divfree_frac_bits texels for bilinear/trilinear (nearest tracks whole
  // texels), and at most divfree_cap grid steps per axis per pixel.
  unsigned divfree_frac_bits = 4;
  unsigned divfree_cap = 64;

  // LOD: fractional bits of the LOD, and index bits of the log2 table (log2(1+f), midpoint entries).
  unsigned lod_frac_bits = 8;
  unsigned lod_log_index_bits = 10;
  // The LOD unit takes the six plane gradients (uq, vq, q along x and y) in a per-triangle block
  // floating-point form: all shifted right by one common amount so the largest has this many bits.
  unsigned lod_grad_bits = 24;

  unsigned filter_weight_bits = 8;  // bilinear and trilinear weights (fixed by the texture unit)

  // Gouraud colour: false = linear in screen space (planes of the vertex colours, no division);
  // true = perspective-correct (planes of colour * q, divided by q per pixel in the reciprocal
  // unit with pixel_nr_steps, whatever the texture coordinates' method).
  bool perspective_color = false;

  // What is built. Bit i of methods is Method(i), of filters Filter(i), of formats TexFormat(i).
  uint32_t methods = 0x3F;  // affine, subdiv, recip_lut, recip_nr, divfree, quadratic
  uint32_t filters = 0x7;
  uint32_t formats = 0x7;

  bool has_method(Method m) const { return (methods >> static_cast<unsigned>(m)) & 1u; }
  bool has_filter(Filter f) const { return (filters >> static_cast<unsigned>(f)) & 1u; }
  bool has_format(TexFormat f) const { return (formats >> static_cast<unsigned>(f)) & 1u; }
  fw::RecordFormat record_format() const;
  // Setup's parameters for the firmware's setup library (htx/fw/tri_setup.h); recip.table is null.
  fw::SetupParams setup_params() const;
  // Throws std::invalid_argument naming the field when a width is outside what the model supports.
  void validate() const;
};

// Named configurations: "icebreaker" (iCE40 UP5K: narrow, shared iterative reciprocal unit,
// RGB565/RGBA4444, no trilinear) and "full" (wide, pipelined, everything built).
// Throws std::invalid_argument for an unknown name, listing the known ones.
const ModelConfig& model_config(std::string_view name);
std::vector<std::string> model_config_names();

// The methods the board's GPU builds (AFFINE and RECIP_LUT: the design the synthesis report's
// gpu_icebreaker_up5k measures). "icebreaker" restricted to them is the board's configuration.
uint32_t icebreaker_board_methods();

// The board's configuration, named so (refusals say `icebreaker-board`): `icebreaker` (or a
// configuration built from it, such as the rtl engine's) with the board's methods only.
inline constexpr const char* kIcebreakerBoard = "icebreaker-board";
ModelConfig icebreaker_board_config(ModelConfig icebreaker);
// The named configuration a configuration's widths and tables are those of: the board's is
// `icebreaker`'s.
std::string_view config_base_name(const ModelConfig& c);

}  // namespace htx
