// Video scan-out driver (hw/regs/video.json, docs/video.md): the framebuffer shown as 640x480 at
// 60 Hz on a board's DVI/HDMI connector. Every access is a register access, so the polling loops
// end in the host simulation too.
#pragma once

#include <stdint.h>

#include "htx/hal/regs.h"

namespace htx::hal {

struct VideoMode {
  uint32_t src_width;   // framebuffer pixels a line shown
  uint32_t src_height;  // framebuffer lines shown
  uint32_t scale;       // each is scale x scale picture pixels
};

inline VideoMode video_mode() {
  const uint32_t m = HTX_VIDEO->MODE;
  return {(m & VIDEO_MODE_SRC_WIDTH_Msk) >> VIDEO_MODE_SRC_WIDTH_Pos,
          (m & VIDEO_MODE_SRC_HEIGHT_Msk) >> VIDEO_MODE_SRC_HEIGHT_Pos,
          (m & VIDEO_MODE_SCALE_Msk) >> VIDEO_MODE_SCALE_Pos};
}

// Shows the framebuffer (or a black picture) from the next frame on.
inline void video_enable(bool on) {
  HTX_VIDEO->CTRL = on ? VIDEO_CTRL_ENABLE_Msk : 0u;
}
inline bool video_enabled() {
  return (HTX_VIDEO->CTRL & VIDEO_CTRL_ENABLE_Msk) != 0;
}

// Frames scanned since reset (each counted as its vertical blanking begins).
inline uint32_t video_frames() {
  return HTX_VIDEO->FRAME;
}

// Whether a line was shown before it had been read whole since the last clear, and the clear.
inline bool video_underrun() {
  return (HTX_VIDEO->STATUS & VIDEO_STATUS_UNDERRUN_Msk) != 0;
}
inline void video_clear_underrun() {
  HTX_VIDEO->STATUS = VIDEO_STATUS_UNDERRUN_Msk;
}

}  // namespace htx::hal
