// One slave side of the htx valid/ready bus as seen by a master under test: drives ready and the
// response channel, optionally with random wait states on both, and checks the master keeps the
// protocol (a request that waits for ready stays presented and unchanged).
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <string>

namespace htx::cpu_tb {

struct BusRequest {
  bool valid = false;
  uint32_t addr = 0;
  bool we = false;
  uint8_t be = 0;
  uint32_t wdata = 0;
};

struct BusResponse {
  bool valid = false;
  uint32_t rdata = 0;
  bool err = false;
};

class BusPortModel {
 public:
  // seed == 0: no wait states (ready always high, responses one cycle after acceptance).
  BusPortModel(std::string name, uint64_t seed);

  // Inputs for the master in this cycle; call before evaluating the model.
  void drive(uint64_t cycle, bool& ready, BusResponse& rsp);
  // The master's request after evaluation. Returns the request if it transfers this cycle.
  // Throws std::runtime_error on a protocol violation.
  std::optional<BusRequest> sample(uint64_t cycle, const BusRequest& req);
  // Queue the response for a transferred request (in order, at least one cycle later).
  void respond(uint64_t cycle, uint32_t rdata, bool err);

 private:
  struct Pending {
    uint64_t due;
    uint32_t rdata;
    bool err;
  };
  std::string name_;
  bool stalls_;
  std::mt19937_64 rng_;
  bool ready_ = true;
  bool rsp_presented_ = false;
  BusRequest waiting_;  // request seen valid && !ready in the previous cycle
  bool has_waiting_ = false;
  std::deque<Pending> pending_;
  uint64_t last_due_ = 0;
};

}  // namespace htx::cpu_tb
