// Per-triangle state as the firmware holds it, and its state word (the first FIFO word of every
// triangle; layout of hw/regs/raster.json register STATE).
#pragma once

#include <stdint.h>

namespace htx::render {

// Method numbers of the state word; kMethodAuto is resolved by the firmware (auto_method.h) and
// never sent.
enum MethodId : uint8_t {
  kMethodAffine = 0,
  kMethodSubdiv = 1,
  kMethodRecipLut = 2,
  kMethodRecipNr = 3,
  kMethodDivFree = 4,
  kMethodAuto = 7,
};

struct TriState {
  uint8_t method = kMethodRecipNr;
  uint8_t subdiv_n = 16;
  uint8_t filter = 1;      // 0 nearest, 1 bilinear, 2 trilinear
  uint8_t wrap_u = 0, wrap_v = 0;  // 0 repeat, 1 clamp, 2 mirror
  uint8_t depth_func = 1;  // 0 never, 1 less, 2 lequal, 3 equal, 4 greater, 5 always
  bool depth_write = true;
  bool textured = true;
  bool gouraud = true;
  uint8_t combine = 1;     // 0 replace, 1 modulate
  uint8_t texture = 0;
};

// The state word with `method` in place of state.method (the resolved one).
uint32_t pack_state_word(const TriState& state, uint8_t method);

}  // namespace htx::render
