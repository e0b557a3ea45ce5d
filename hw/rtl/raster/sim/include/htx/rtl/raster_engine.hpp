// Engine `rtl`: the same ScreenScene the `model` engine takes, encoded into vertex records by the
// firmware's encoder exactly as the model encodes them, its textures uploaded through the texture
// memory window and TEXTURE descriptors, the records pushed through RASTER.FIFO of the Verilated GPU
// (htx_gpu_full / htx_gpu_icebreaker, docs/gpu.md), and read back from its framebuffer and depth
// memories.
#pragma once

#include <cstdint>
#include <string>

#include "htx/model/config.hpp"
#include "htx/model/types.hpp"

namespace htx {

struct RtlStats {
  uint64_t cycles = 0;          // clocks the raster unit was busy drawing (CNT_BUSY; the clear excluded)
  uint64_t feed_cycles = 0;     // clocks from the first FIFO word to idle, as the host saw them
  uint64_t covered_pixels = 0;  // fragments traversal produced (CNT_FRAGMENTS)
  uint64_t pixels_written = 0;  // CNT_PIXELS
  uint64_t triangles = 0;       // triangles taken from the FIFO (CNT_TRIANGLES)
  uint64_t triangles_encoded = 0;  // triangles the encoder accepted
  // ... and the host pushed: all of them, or (CAPS.FW_SETUP) those whose setup draws something
  uint64_t triangles_sent = 0;
  uint64_t setup_busy_cycles = 0;
  uint64_t stall_input = 0, stall_setup = 0, stall_fragment = 0;
  uint64_t clear_cycles = 0;    // clocks of the fast clear before drawing
  uint64_t divfree_steps = 0;   // CNT_DIVFREE_STEPS (u + v grid steps of DIVFREE fragments)
  double px_per_clk = 0;        // covered_pixels / cycles
  double setup_cycles_per_triangle = 0;
};

// Renders textured and untextured triangles (Gouraud colour perspective-correct in `full`, linear in
// screen space in `icebreaker`). Texture t goes to slot t. Throws std::invalid_argument when the
// configuration is not one the RTL builds (the named `full` and `icebreaker` with their exact field
// values, perspective_color included, and the methods a subset of the built ones; rtl_config()
// gives the configuration the RTL renders), when a triangle asks for a method, filter or format the
// configuration does not build,
// names a texture beyond the built slots (8 / 4) or a bad texture, when the textures exceed the
// Verilated texture memory (128K / 16K texels), or the frame exceeds the 262144-pixel memories or
// 4096 per side. An `icebreaker` configuration whose methods are AFFINE and RECIP_LUT at most is
// rendered on the GPU built with only those (the board's, as the synthesis report measures it:
// htx_gpu_icebreaker with Methods 5'b00101); any other on the one with every method.
Frame render_rtl(const ScreenScene& scene, const ModelConfig& config, RtlStats* stats = nullptr);

// The named configuration as the RTL builds it: model_config(name) with the built methods (affine,
// subdiv, recip_lut, recip_nr, divfree; not the model's quadratic). Throws like model_config.
ModelConfig rtl_config(const std::string& name);

// `icebreaker` with the board's methods only (AFFINE, RECIP_LUT): render_rtl draws it on the GPU
// the synthesis report measures.
ModelConfig rtl_board_config();

// The per-triangle state word (hw/regs/raster.json register STATE) of a triangle. For DIVFREE the
// SUBDIV_N field carries divfree_top, the texture's last mip level (level_count - 1; 0 untextured),
// which bilinear and trilinear need for their per-span level choice.
uint32_t pack_state_word(const TriState& state, Method resolved_method, unsigned divfree_top = 0);

// Pixels whose colour or depth differ between two frames of the same size (throws otherwise).
uint64_t frame_mismatch_pixels(const Frame& a, const Frame& b);

}  // namespace htx
