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

// The methods' and filters' names by number, as the console's `set` and `info` spell them (SUBDIV
// is `subdivN` in `set method`); the host reads `info` with the same table.
inline constexpr const char* kMethodNames[] = {"affine", "subdiv", "recip_lut", "recip_nr", "divfree"};
inline constexpr uint32_t kMethodNameCount = sizeof kMethodNames / sizeof kMethodNames[0];
static_assert(kMethodSubdiv == 1 && kMethodDivFree == kMethodNameCount - 1, "kMethodNames follows MethodId");
inline constexpr const char* kFilterNames[] = {"nearest", "bilinear", "trilinear"};
inline constexpr uint32_t kFilterNameCount = sizeof kFilterNames / sizeof kFilterNames[0];

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
