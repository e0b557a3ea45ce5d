// The plane record: a triangle after setup, as the firmware sends it to a raster unit that leaves
// setup to it (CAPS.FW_SETUP; the `icebreaker` configuration, docs/raster.md "Plane record"). It
// holds what the unit's own setup would hand its traversal: the box, the edge functions' signs and
// thresholds, and the words of its plane RAM (the three edge functions and the attribute planes at
// the box's first pixel centre, with their gradients). Freestanding C++17 on tri_setup.h, so the
// words are the model's setup bit for bit.
//
// Words (all little-endian 32-bit, FIFO order):
//   0  the state word (register STATE's layout)
//   1  flat colour: vertex 0's rgba
//   2  x_lo [12:0], x_hi [28:16]    the pixel box, clipped to the screen, x_lo <= x_hi < width
//   3  y_lo [12:0], y_hi [28:16]
//   4  flags: thr [2:0], a_neg [5:3], a_zero [8:6], e_neg [11:9], det_neg [12]
//   5  u_offset   6  v_offset
//   DIVFREE (method 4) only: 18 words, DIVFREE's side band LSB first (kPlaneSideWords)
//   then pairs of words, one plane-RAM word each: low = data [31:0]; high = data [55:32] in
//   [23:0], index [27:24], select [29:28] (0 g_x, 1 g_y, 2 start value), LAST [31] on the
//   record's final pair.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "htx/fw/tri_setup.h"
#include "htx/fw/vertex_record.h"

namespace htx::fw {

inline constexpr size_t kPlaneHeaderWords = 7;
inline constexpr size_t kPlaneSideWords = 18;
inline constexpr size_t kPlaneRamWords = 10;  // edges 0..2, z, r, g, b, q, uq (AFFINE: u), vq (v)
inline constexpr size_t kPlaneRecordMaxWords = kPlaneHeaderWords + kPlaneSideWords + 2 * 3 * kPlaneRamWords;

// Fields of the high word of a plane pair.
inline constexpr uint32_t kPlaneIndexPos = 24;
inline constexpr uint32_t kPlaneSelectPos = 28;
inline constexpr uint32_t kPlaneLastBit = 1u << 31;
enum PlaneSelect : uint32_t { kPlaneGx = 0, kPlaneGy = 1, kPlaneStart = 2 };

// Flags word.
inline constexpr uint32_t kPlaneFlagThrPos = 0, kPlaneFlagANegPos = 3, kPlaneFlagAZeroPos = 6;
inline constexpr uint32_t kPlaneFlagENegPos = 9, kPlaneFlagDetNeg = 1u << 12;

// What setup needs beyond the record: the configuration's parameters (recip.table filled, or null),
// the screen, the triangle's state word and method (0 AFFINE ... 4 DIVFREE), and whether the unit
// builds texture mapping (CAPS.METHODS != 0): only then are the q, uq, vq planes sent (a unit
// without it has no room for them in its plane RAM). Every triangle gets every plane the unit has,
// textured or not, as its own setup gave them: the texture port and DIVFREE's walk see the same
// coordinates either way.
struct PlaneJob {
  const SetupParams* params = nullptr;
  int32_t width = 0, height = 0;
  uint32_t state_word = 0;
  uint32_t method = 0;
  bool texture_planes = true;
};

enum PlaneStatus : int {
  kPlaneOk = 0,
  kPlaneEmpty = 1,    // draws nothing (zero area, or no pixel centre of the screen in its box):
                      // not sent, as the unit's own setup would drop it
  kPlaneTooWide = 2,  // the parameters need more than 64-bit setup (plane_record_fits); not sent
};

// Plane records are set up in 64-bit arithmetic (tri_setup.h's *_64 functions): the reciprocal's
// W <= 30 and every plane's numerators within 64 bits, as in the `icebreaker` formats.
constexpr bool plane_record_fits(const SetupParams& p) {
  const uint32_t dw = uint32_t{p.format.xy_int_bits} + 9;                  // coordinate deltas, signed
  const uint32_t uq = uint32_t{p.format.q_bits} + p.format.uv_int_bits;     // uq, vq (signed)
  const uint32_t ua = uint32_t{p.format.uv_int_bits} + p.texcoord_frac_bits; // AFFINE's u_i (signed)
  // make_plane_64's |value| < 2^36 (37 bits signed; z and q unsigned: 36 bits); AFFINE's uq_i 2^-s
  // with s >= 1 - W (q < 2^W) within 64 bits.
  return p.recip.width <= 30 && uq <= 37 && ua <= 37 && p.format.z_bits <= 36 && p.format.q_bits <= 36 &&
         uq + p.recip.width - 1 <= 63 && dw <= 25;
}
static_assert(plane_record_fits(kIcebreakerSetup), "the board's setup fits 64-bit arithmetic");

// Sets up one triangle and writes its plane record to out (kPlaneRecordMaxWords at most), its
// length to *words (0 unless kPlaneOk).
PlaneStatus encode_plane_record(const PlaneJob& job, const TriangleRecord& rec, uint32_t* out, size_t* words);

}  // namespace htx::fw
