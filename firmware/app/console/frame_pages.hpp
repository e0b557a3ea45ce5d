// Double or triple buffering for the console's renders (docs/video.md, "Double buffering"): where
// the GPU has two or three colour pages and the video unit can show each, a render draws into a
// page neither shown nor waiting to be, and the video flips to it at its next frame start, so a
// screen never shows a frame half drawn. Every frame drawn is shown, for at least one video frame.
// With three pages a render never waits to begin: it draws while the frame before it waits for its
// flip, and waits only to present, when that flip has not been taken yet (a render faster than
// the video's frame); with two pages it waits to begin until the last flip is taken; with one
// everything draws into page 0 and nothing flips.
#pragma once

#include <stdint.h>

namespace console_app {

// Chooses the page the next render draws into (the raster unit is idle between renders): one the
// video neither shows nor is to flip to; with two pages, after waiting for the last flip to take
// (at most one frame, bounded by max_polls status reads; should the video never flip, the render
// draws anyway).
void begin_frame_page(uint32_t max_polls);

// Shows the page just drawn from the video's next frame start on, after the frame drawn before it
// has been shown (at most one frame, bounded by max_polls status reads).
void present_frame_page(uint32_t max_polls);

// The pages there are (1, 2 or 3) and the one the video shows now, for `info`.
uint32_t frame_pages();
uint32_t shown_frame_page();

}  // namespace console_app
