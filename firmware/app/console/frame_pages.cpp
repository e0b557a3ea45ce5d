#include "frame_pages.hpp"

#include "htx/hal/framebuffer.h"
#include "htx/hal/video.h"

namespace console_app {

uint32_t frame_pages() {
  const uint32_t fb = htx::hal::fb_pages(), video = htx::hal::video_pages();
  const uint32_t pages = fb < video ? fb : video;
  return pages >= 2 ? pages : 1u;
}

uint32_t shown_frame_page() { return htx::hal::video_shown_page(); }

void begin_frame_page(uint32_t max_polls) {
  const uint32_t pages = frame_pages();
  if (pages < 2) return;
  // The page to draw is neither the one the video shows now nor the one it is to flip to (the
  // frame drawn last). With three pages there always is one; with two, the video must first take
  // the flip, at its next frame start, whether or not it is enabled: within a frame (420,000
  // clocks), usually long before the next command arrives.
  const uint32_t requested = htx::hal::video_requested_page();
  uint32_t shown = htx::hal::video_shown_page();
  for (uint32_t i = 0; pages == 2 && shown != requested && i < max_polls; ++i) shown = htx::hal::video_shown_page();
  uint32_t draw = 0;
  while (draw == requested || draw == shown) ++draw;
  // (Two pages and a video that never flipped: the page not requested, drawn while shown.)
  htx::hal::fb_set_draw_page(draw < pages ? draw : requested ^ 1u);
}

void present_frame_page(uint32_t max_polls) {
  if (frame_pages() < 2) return;
  // A frame still waiting to be shown is shown first (three pages): the flip to it is taken
  // within a frame, and a newer request would otherwise replace it unseen.
  const uint32_t requested = htx::hal::video_requested_page();
  for (uint32_t i = 0; htx::hal::video_shown_page() != requested && i < max_polls; ++i) {
  }
  htx::hal::video_show_page(htx::hal::fb_draw_page());
}

}  // namespace console_app
