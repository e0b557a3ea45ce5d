#include "htx/rtl/fifo_records.hpp"

#include <stdexcept>

#include "htx_regs.h"

namespace htx::rtl {

FifoRecords::FifoRecords(const ModelConfig& cfg, uint32_t caps, int width, int height)
    : params_(cfg.setup_params()),
      fw_setup_((caps & RASTER_CAPS_FW_SETUP_Msk) != 0),
      texture_planes_((caps & RASTER_CAPS_METHODS_Msk) != 0),
      width_(width),
      height_(height) {
  table_.resize(size_t{1} << params_.recip.k);
  fw::recip_fill_table(params_.recip.k, params_.recip.g, table_.data());
  params_.recip.table = table_.data();
}

bool FifoRecords::append(std::vector<uint32_t>* words, uint32_t state_word, const fw::TriangleRecord& rec) const {
  if (!fw_setup_) {
    uint32_t packed[fw::kTriangleWords];
    fw::pack_triangle(rec, packed);
    words->push_back(state_word);
    words->insert(words->end(), packed, packed + fw::kTriangleWords);
    return true;
  }
  fw::PlaneJob job;
  job.params = &params_;
  job.width = width_;
  job.height = height_;
  job.state_word = state_word;
  job.method = (state_word & RASTER_STATE_METHOD_Msk) >> RASTER_STATE_METHOD_Pos;
  job.texture_planes = texture_planes_;
  uint32_t out[fw::kPlaneRecordMaxWords];
  size_t n = 0;
  const fw::PlaneStatus status = fw::encode_plane_record(job, rec, out, &n);
  if (status == fw::kPlaneTooWide)
    throw std::logic_error("plane records: this configuration's setup does not fit 64-bit arithmetic");
  words->insert(words->end(), out, out + n);
  return status == fw::kPlaneOk;
}

}  // namespace htx::rtl
