// Double buffering for the console's renders (docs/video.md, "Double buffering"): where the GPU
// has two colour pages and the video unit can show either, each render draws into the page not
// shown and the video flips to it at its next frame start, so a screen never shows a frame half
// drawn. With one page everything draws into page 0 and nothing flips.
#pragma once

#include <stdint.h>

namespace console_app {

// Chooses the page the next render draws into (the raster unit is idle between renders): the
// one the video is not showing, after waiting for the last flip to take (at most one frame,
// bounded by max_polls status reads; should the video never flip, the render draws anyway).
void begin_frame_page(uint32_t max_polls);

// Shows the page just drawn from the video's next frame start on.
void present_frame_page();

// The pages there are (1 or 2) and the one the video shows now, for `info`.
uint32_t frame_pages();
uint32_t shown_frame_page();

}  // namespace console_app
