// A raster unit's FIFO stream of triangles, in the form its build takes: vertex records for a unit
// with setup of its own, plane records (htx/fw/plane_record.h) for one whose CAPS has FW_SETUP, set
// up here with the firmware's own library as the firmware does on the SoC (hal/include/htx/hal/raster.h).
#pragma once

#include <cstdint>
#include <vector>

#include "htx/fw/plane_record.h"
#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"

namespace htx::rtl {

class FifoRecords {
 public:
  // cfg: the unit's configuration (its formats and setup parameters); caps: its CAPS register; the
  // screen (FB_SIZE) the triangles are set up for.
  FifoRecords(const ModelConfig& cfg, uint32_t caps, int width, int height);

  bool fw_setup() const { return fw_setup_; }

  // Appends the triangle's words, its state word first. With FW_SETUP a triangle that draws
  // nothing (zero area, no pixel centre on the screen) is not sent, as the firmware does not send
  // it: returns false then.
  bool append(std::vector<uint32_t>* words, uint32_t state_word, const fw::TriangleRecord& rec) const;

 private:
  fw::SetupParams params_;
  std::vector<uint32_t> table_;
  bool fw_setup_;
  bool texture_planes_;  // CAPS.METHODS != 0: the q, uq, vq planes are sent
  int width_, height_;
};

}  // namespace htx::rtl
