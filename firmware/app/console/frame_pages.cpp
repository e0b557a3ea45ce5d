#include "frame_pages.hpp"

#include "htx/hal/framebuffer.h"
#include "htx/hal/video.h"

namespace console_app {

uint32_t frame_pages() {
  return (htx::hal::fb_pages() >= 2 && htx::hal::video_pages() >= 2) ? 2u : 1u;
}

uint32_t shown_frame_page() { return htx::hal::video_shown_page(); }

void begin_frame_page(uint32_t max_polls) {
  if (frame_pages() < 2) return;
  // The video takes a flip at its next frame start, whether or not it is enabled, so this ends
  // within a frame (420,000 clocks); it is usually over long before the next command arrives.
  const uint32_t requested = htx::hal::video_requested_page();
  bool flipped = false;
  for (uint32_t i = 0; i < max_polls && !flipped; ++i) flipped = htx::hal::video_shown_page() == requested;
  htx::hal::fb_set_draw_page(requested ^ 1u);
}

void present_frame_page() {
  if (frame_pages() < 2) return;
  htx::hal::video_show_page(htx::hal::fb_draw_page());
}

}  // namespace console_app
