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
  // (The masks are unsigned long: 64 bits on a host.)
  return {static_cast<uint32_t>((m & VIDEO_MODE_SRC_WIDTH_Msk) >> VIDEO_MODE_SRC_WIDTH_Pos),
          static_cast<uint32_t>((m & VIDEO_MODE_SRC_HEIGHT_Msk) >> VIDEO_MODE_SRC_HEIGHT_Pos),
          static_cast<uint32_t>((m & VIDEO_MODE_SCALE_Msk) >> VIDEO_MODE_SCALE_Pos)};
}

// Shows the framebuffer (or a black picture) from the next frame on; the page shown stays.
inline void video_enable(bool on) {
  const uint32_t page = HTX_VIDEO->CTRL & VIDEO_CTRL_PAGE_Msk;
  HTX_VIDEO->CTRL = page | (on ? VIDEO_CTRL_ENABLE_Msk : 0u);
}
inline bool video_enabled() {
  return (HTX_VIDEO->CTRL & VIDEO_CTRL_ENABLE_Msk) != 0;
}

// Colour pages the unit can show (MODE.PAGES: 3 where the GPU triple-buffers).
inline uint32_t video_pages() {
  return (HTX_VIDEO->MODE & VIDEO_MODE_PAGES_Msk) >> VIDEO_MODE_PAGES_Pos;
}

// Shows colour page `page` from the next frame's start on (the enable stays). The frame being
// scanned keeps its page, so a flip never splits a frame: video_shown_page() says when it took.
inline void video_show_page(uint32_t page) {
  const uint32_t enable = HTX_VIDEO->CTRL & VIDEO_CTRL_ENABLE_Msk;
  HTX_VIDEO->CTRL = enable | ((page << VIDEO_CTRL_PAGE_Pos) & VIDEO_CTRL_PAGE_Msk);
}
inline uint32_t video_requested_page() {
  return (HTX_VIDEO->CTRL & VIDEO_CTRL_PAGE_Msk) >> VIDEO_CTRL_PAGE_Pos;
}
// The page the frame being scanned shows.
inline uint32_t video_shown_page() {
  return (HTX_VIDEO->STATUS & VIDEO_STATUS_PAGE_Msk) >> VIDEO_STATUS_PAGE_Pos;
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
