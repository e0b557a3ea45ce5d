// Raster unit driver (hw/regs/raster.json): framebuffer set-up, fast clear, the vertex FIFO, the
// performance counters and what the build has (CAPS). A triangle is one state word (layout of
// register STATE) followed by the kTriangleWords words of htx::fw::pack_triangle; a unit that
// leaves setup to the firmware (CAPS.FW_SETUP) takes it as a plane record instead, which
// raster_push_triangle makes (htx/fw/plane_record.h).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "htx/fw/plane_record.h"
#include "htx/fw/tri_setup.h"
#include "htx/fw/vertex_record.h"
#include "htx/hal/regs.h"

namespace htx::hal {

// What this build of the raster unit has (register CAPS).
struct RasterCaps {
  uint32_t methods = 0;   // bit m = perspective method m (STATE.METHOD) is built
  bool counters = false;  // the CNT_* counters are built (the board's build leaves them out)
  bool fw_setup = false;  // the FIFO takes plane records: setup is the firmware's
};

inline RasterCaps raster_caps() {
  const uint32_t c = HTX_RASTER->CAPS;
  RasterCaps r;
  r.methods = (c & RASTER_CAPS_METHODS_Msk) >> RASTER_CAPS_METHODS_Pos;
  r.counters = (c & RASTER_CAPS_COUNTERS_Msk) != 0;
  r.fw_setup = (c & RASTER_CAPS_FW_SETUP_Msk) != 0;
  return r;
}

// built = false: the unit has no counters (CAPS.COUNTERS = 0) and every count reads 0.
struct RasterCounters {
  bool built = false;
  uint32_t busy = 0, stall_input = 0, stall_setup = 0, stall_fragment = 0, setup_busy = 0;
  uint32_t triangles = 0, fragments = 0, pixels = 0, divfree_steps = 0;
};

// Drops everything queued or in flight (FIFO, setup, traversal, a clear) and leaves the unit
// enabled and idle. Pixels already written stay.
inline void raster_abort() { HTX_RASTER->CTRL = RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_ABORT_Msk; }

// Screen size (1..4096 each) and row stride in pixels; traversal clips every triangle to the size.
// Not checked here (render_frame checks its viewport first): each field keeps its low 13 bits, so
// 8192 would be 0, an empty screen.
inline void raster_configure(uint32_t width, uint32_t height, uint32_t stride) {
  HTX_RASTER->FB_SIZE = ((width << RASTER_FB_SIZE_WIDTH_Pos) & RASTER_FB_SIZE_WIDTH_Msk) |
                        ((height << RASTER_FB_SIZE_HEIGHT_Pos) & RASTER_FB_SIZE_HEIGHT_Msk);
  HTX_RASTER->FB_STRIDE = (stride << RASTER_FB_STRIDE_PIXELS_Pos) & RASTER_FB_STRIDE_PIXELS_Msk;
}

// Starts a fast clear of the colour and/or depth buffer. Call it while the unit is idle
// (raster_busy() false): the clear overtakes triangles still in the FIFO (it starts once setup and
// traversal are empty), a second request while one waits replaces it, and the clear reads
// CLEAR_COLOR, CLEAR_DEPTH, FB_STRIDE and FB_PAGE while it runs (CTRL.CLEAR_COLOR).
inline void raster_clear(bool color, uint16_t rgb565, bool depth, uint32_t z) {
  HTX_RASTER->CLEAR_COLOR = (static_cast<uint32_t>(rgb565) << RASTER_CLEAR_COLOR_RGB565_Pos) & RASTER_CLEAR_COLOR_RGB565_Msk;
  HTX_RASTER->CLEAR_DEPTH = (z << RASTER_CLEAR_DEPTH_Z_Pos) & RASTER_CLEAR_DEPTH_Z_Msk;
  HTX_RASTER->CTRL = RASTER_CTRL_ENABLE_Msk | (color ? RASTER_CTRL_CLEAR_COLOR_Msk : 0u) |
                     (depth ? RASTER_CTRL_CLEAR_DEPTH_Msk : 0u);
}

// Writes words into the vertex FIFO. A full FIFO holds each bus write until there is room
// (back-pressure), so no word is dropped and no polling is needed.
inline void raster_push(const uint32_t* words, size_t n) {
  for (size_t i = 0; i < n; ++i) HTX_RASTER->FIFO = words[i];
}

// Setup's parameters for a unit with CAPS.FW_SETUP: the `icebreaker` configuration's, the only
// build that leaves setup to the firmware (its formats are the ones the firmware encodes for it).
// The reciprocal table (2^k words) is filled on first use.
inline const fw::SetupParams& raster_fw_setup_params() {
  static uint32_t table[uint32_t{1} << fw::kIcebreakerSetup.recip.k];
  static fw::SetupParams params = fw::kIcebreakerSetup;  // (constant-initialised: no guard)
  if (params.recip.table == nullptr) {
    fw::recip_fill_table(params.recip.k, params.recip.g, table);
    params.recip.table = table;
  }
  return params;
}

// The setup job of a triangle with this state word, from the unit's FB_SIZE and CAPS register
// values (no register access: geombench times the same job without a unit).
inline fw::PlaneJob raster_plane_job(uint32_t state_word, uint32_t fb_size, uint32_t caps) {
  fw::PlaneJob job;
  job.params = &raster_fw_setup_params();
  job.width = static_cast<int32_t>((fb_size & RASTER_FB_SIZE_WIDTH_Msk) >> RASTER_FB_SIZE_WIDTH_Pos);
  job.height = static_cast<int32_t>((fb_size & RASTER_FB_SIZE_HEIGHT_Msk) >> RASTER_FB_SIZE_HEIGHT_Pos);
  job.state_word = state_word;
  job.method = (state_word & RASTER_STATE_METHOD_Msk) >> RASTER_STATE_METHOD_Pos;
  job.texture_planes = (caps & RASTER_CAPS_METHODS_Msk) != 0;
  return job;
}

// Sets the triangle up for the screen in FB_SIZE and queues its plane record; a triangle that
// draws nothing there is not sent (kPlaneEmpty). caps: the unit's CAPS, as the caller read it.
// (kPlaneTooWide cannot happen with these parameters: plane_record.h asserts it.)
inline fw::PlaneStatus raster_push_plane_record(uint32_t state_word, const fw::TriangleRecord& rec, uint32_t caps) {
  const fw::PlaneJob job = raster_plane_job(state_word, HTX_RASTER->FB_SIZE, caps);
  uint32_t words[fw::kPlaneRecordMaxWords];
  size_t n = 0;
  const fw::PlaneStatus status = fw::encode_plane_record(job, rec, words, &n);
  raster_push(words, n);
  return status;
}

// Queues a triangle: its state word and packed vertex record, or (CAPS.FW_SETUP) its plane record.
inline void raster_push_triangle(uint32_t state_word, const uint32_t words[fw::kTriangleWords]) {
  const uint32_t caps = HTX_RASTER->CAPS;
  if (caps & RASTER_CAPS_FW_SETUP_Msk) {
    fw::TriangleRecord rec;
    fw::unpack_triangle(words, &rec);
    raster_push_plane_record(state_word, rec, caps);
    return;
  }
  HTX_RASTER->FIFO = state_word;
  raster_push(words, fw::kTriangleWords);
}

inline bool raster_busy() { return (HTX_RASTER->STATUS & RASTER_STATUS_BUSY_Msk) != 0; }

// Polls STATUS until the unit is idle, at most max_polls times; returns false on a timeout.
inline bool raster_wait_idle(uint32_t max_polls) {
  for (uint32_t i = 0; i < max_polls; ++i)
    if (!raster_busy()) return true;
  return false;
}

// A triangle asked for something the configuration does not build since the last clear_error.
inline bool raster_state_error() { return (HTX_RASTER->STATUS & RASTER_STATUS_ERR_STATE_Msk) != 0; }
inline void raster_clear_state_error() { HTX_RASTER->STATUS = RASTER_STATUS_ERR_STATE_Msk; }

inline void raster_reset_counters() { HTX_RASTER->CTRL = RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_COUNTERS_RESET_Msk; }

inline void raster_read_counters(RasterCounters* c) {
  c->built = raster_caps().counters;
  c->busy = HTX_RASTER->CNT_BUSY;
  c->stall_input = HTX_RASTER->CNT_STALL_INPUT;
  c->stall_setup = HTX_RASTER->CNT_STALL_SETUP;
  c->stall_fragment = HTX_RASTER->CNT_STALL_FRAGMENT;
  c->setup_busy = HTX_RASTER->CNT_SETUP_BUSY;
  c->triangles = HTX_RASTER->CNT_TRIANGLES;
  c->fragments = HTX_RASTER->CNT_FRAGMENTS;
  c->pixels = HTX_RASTER->CNT_PIXELS;
  c->divfree_steps = HTX_RASTER->CNT_DIVFREE_STEPS;
}

}  // namespace htx::hal
