// What the render firmware assumes about the SoC's raster unit: the `icebreaker` configuration
// (docs/soc.md, "GPU"). Its record widths and AUTO's bounds are compiled in (the system test checks
// them against htx::rtl_config("icebreaker")); the methods it builds are read from CAPS.METHODS.
#pragma once

#include <stdint.h>

#include "htx/fw/auto_select.h"
#include "htx/fw/vertex_record.h"
#include "htx/render/fixed.h"

namespace render_app {

// Vertex-record field widths of the icebreaker raster unit (ModelConfig::record_format()).
inline constexpr htx::fw::RecordFormat kRecordFormat{12, 16, 24, 13};
// AUTO: the icebreaker raster unit's reciprocal bounds and costs, and issue 7's tolerance of 1/16
// texel (Q16.16).
inline constexpr htx::fw::AutoConfig kAutoConfig = htx::fw::kAutoConfigIcebreaker;
inline constexpr int64_t kAutoTolerance = htx::render::kOne / 16;
// Screen: 160 x 120 fits the SoC's framebuffer of 19,200 pixels.
inline constexpr int32_t kWidth = 160;
inline constexpr int32_t kHeight = 120;
inline constexpr uint16_t kClearColor = 0x1234;  // RGB565
inline constexpr uint32_t kClearDepth = 0xFFFFFF;

}  // namespace render_app
