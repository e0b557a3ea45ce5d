#include "bus_port_model.hpp"

#include <cstdio>
#include <stdexcept>

namespace htx::cpu_tb {

BusPortModel::BusPortModel(std::string name, uint64_t seed)
    : name_(std::move(name)), stalls_(seed != 0), rng_(seed) {}

void BusPortModel::drive(uint64_t cycle, bool& ready, BusResponse& rsp) {
  if (stalls_) {
    // Mostly ready, with runs of wait states now and then.
    const uint64_t r = rng_() % 100;
    ready_ = r >= 35;
  } else {
    ready_ = true;
  }
  ready = ready_;
  rsp = BusResponse{};
  rsp_presented_ = !pending_.empty() && pending_.front().due <= cycle;
  if (rsp_presented_) {
    rsp.valid = true;
    rsp.rdata = pending_.front().rdata;
    rsp.err = pending_.front().err;
  }
}

std::optional<BusRequest> BusPortModel::sample(uint64_t cycle, const BusRequest& req) {
  if (has_waiting_) {
    if (!req.valid) {
      throw std::runtime_error(name_ + ": request withdrawn while waiting for ready at cycle " +
                               std::to_string(cycle));
    }
    if (req.addr != waiting_.addr || req.we != waiting_.we || req.be != waiting_.be ||
        (req.we && req.wdata != waiting_.wdata)) {
      char detail[160];
      std::snprintf(detail, sizeof detail, " (was addr %08x we %d be %x wdata %08x, now %08x %d %x %08x)",
                    waiting_.addr, waiting_.we, waiting_.be, waiting_.wdata, req.addr, req.we, req.be,
                    req.wdata);
      throw std::runtime_error(name_ + ": request changed while waiting for ready at cycle " +
                               std::to_string(cycle) + detail);
    }
  }
  if (rsp_presented_) pending_.pop_front();
  has_waiting_ = req.valid && !ready_;
  if (has_waiting_) waiting_ = req;
  if (!(req.valid && ready_)) return std::nullopt;
  if (pending_.size() > 8) {
    throw std::runtime_error(name_ + ": more than 8 requests outstanding at cycle " + std::to_string(cycle));
  }
  return req;
}

void BusPortModel::respond(uint64_t cycle, uint32_t rdata, bool err) {
  uint64_t delay = 1;
  if (stalls_) {
    const uint64_t r = rng_() % 100;
    if (r < 3) {
      delay += 8 + rng_() % 8;  // an occasional long wait
    } else if (r < 40) {
      delay += 1 + rng_() % 3;
    }
  }
  uint64_t due = cycle + delay;
  if (due <= last_due_) due = last_due_ + 1;  // in order, one response per cycle
  last_due_ = due;
  pending_.push_back(Pending{due, rdata, err});
}

}  // namespace htx::cpu_tb
