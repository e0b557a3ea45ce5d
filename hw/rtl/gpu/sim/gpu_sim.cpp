#include "htx/rtl/gpu_sim.hpp"

#include <cstddef>
#include <stdexcept>

#include "Vhtx_gpu_full.h"
#include "Vhtx_gpu_board.h"
#include "Vhtx_gpu_icebreaker.h"
#include "htx/rtl/two_port_pins.hpp"
#include "htx_regs.h"
#include "verilated.h"

namespace htx::rtl {

// Both configurations share every port name; this hides which one runs.
class GpuPort {
 public:
  virtual ~GpuPort() = default;
  // Drives both request ports, settles the logic with the clock low and returns the ready flags.
  virtual void settle(const PortRequest& reg, const PortRequest& mem, bool* reg_ready, bool* mem_ready) = 0;
  // Rising edge; the responses visible after it.
  virtual void rise(PortResponse* reg, PortResponse* mem) = 0;
  virtual void reset() = 0;
};

namespace {

template <class V>
class VerilatedGpu final : public GpuPort {
 public:
  VerilatedGpu() : ctx_(std::make_unique<VerilatedContext>()), top_(std::make_unique<V>(ctx_.get())) {
    top_->fbv_req_i = 0;  // (no video scan-out here)
    top_->fbv_addr_i = 0;
  }
  ~VerilatedGpu() override { top_->final(); }

  void settle(const PortRequest& r, const PortRequest& m, bool* reg_ready, bool* mem_ready) override {
    settle_ports(*top_, r, m, reg_ready, mem_ready);
  }
  void rise(PortResponse* r, PortResponse* m) override { rise_ports(*top_, r, m); }
  void reset() override { reset_ports(*top_); }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
};

constexpr uint64_t kRequestLimit = 1u << 20;  // clocks a single request may wait before we give up

// One request on one port, held until accepted, then clocked until its response.
PortResponse run_one(GpuPort& port, const PortRequest& req, bool on_mem, uint64_t& cycles) {
  PortResponse r, m;
  bool accepted = false;
  for (uint64_t waited = 0;; ++waited) {
    if (waited > kRequestLimit) throw std::runtime_error("rtl engine: a GPU bus request got no response");
    bool rr = false, mr = false;
    const PortRequest none;
    port.settle(on_mem || accepted ? none : req, on_mem && !accepted ? req : none, &rr, &mr);
    const bool take = !accepted && (on_mem ? mr : rr);
    port.rise(&r, &m);
    ++cycles;
    accepted = accepted || take;
    const PortResponse& o = on_mem ? m : r;
    if (accepted && o.rsp_valid) return o;
  }
}

}  // namespace

GpuSim::GpuSim(const std::string& config) {
  if (config == "full") {
    port_ = std::make_unique<VerilatedGpu<Vhtx_gpu_full>>();
  } else if (config == "icebreaker") {
    port_ = std::make_unique<VerilatedGpu<Vhtx_gpu_icebreaker>>();
  } else if (config == "icebreaker_board") {
    port_ = std::make_unique<VerilatedGpu<Vhtx_gpu_board>>();
  } else {
    throw std::invalid_argument("rtl engine: no Verilated GPU for configuration '" + config +
                                "' (built: full, icebreaker, icebreaker_board)");
  }
  port_->reset();
  const uint32_t caps = read_reg(HTX_TEXTURE_BASE + offsetof(HTX_TEXTURE_Type, CAPS));
  texture_blocks_ = uint32_t{1} << ((caps & TEXTURE_CAPS_BLOCK_BITS_Msk) >> TEXTURE_CAPS_BLOCK_BITS_Pos);
}

GpuSim::~GpuSim() = default;

void GpuSim::idle(uint64_t n) {
  for (uint64_t i = 0; i < n; ++i) {
    bool rr = false, mr = false;
    port_->settle(PortRequest{}, PortRequest{}, &rr, &mr);
    PortResponse r, m;
    port_->rise(&r, &m);
    ++cycles_;
  }
}

uint32_t GpuSim::read_reg(uint32_t addr) {
  const PortRequest q = read_at(addr);
  const PortResponse o = run_one(*port_, q, false, cycles_);
  if (o.rsp_err) throw std::runtime_error("rtl engine: register read at " + std::to_string(addr) + " failed");
  return o.rdata;
}

void GpuSim::write_reg(uint32_t addr, uint32_t value) {
  const PortRequest q = write_at(addr, value);
  if (run_one(*port_, q, false, cycles_).rsp_err)
    throw std::runtime_error("rtl engine: register write at " + std::to_string(addr) + " failed");
}

bool GpuSim::mem_read(uint32_t addr, uint32_t* data) {
  const PortRequest q = read_at(addr);
  const PortResponse o = run_one(*port_, q, true, cycles_);
  *data = o.rdata;
  return o.rsp_err;
}

bool GpuSim::mem_write(uint32_t addr, uint32_t data, uint8_t be) {
  const PortRequest q = write_at(addr, data, be);
  return run_one(*port_, q, true, cycles_).rsp_err;
}

uint64_t GpuSim::mem_write_burst(const std::vector<std::pair<uint32_t, uint32_t>>& addr_data) {
  size_t issued = 0, answered = 0;
  uint64_t errors = 0, waited = 0;
  while (answered < addr_data.size()) {
    PortRequest q;
    q.valid = issued < addr_data.size();
    q.we = true;
    if (q.valid) {
      q.addr = addr_data[issued].first;
      q.wdata = addr_data[issued].second;
    }
    bool rr = false, mr = false;
    port_->settle(PortRequest{}, q, &rr, &mr);
    PortResponse r, m;
    port_->rise(&r, &m);
    ++cycles_;
    if (q.valid && mr) ++issued;
    if (m.rsp_valid) {
      ++answered;
      errors += m.rsp_err;
      waited = 0;
    } else if (++waited > kRequestLimit) {
      throw std::runtime_error("rtl engine: memory writes got no response");
    }
  }
  return errors;
}

void GpuSim::push_words(const std::vector<uint32_t>& words) {
  PortRequest q;
  q.valid = true;
  q.we = true;
  q.addr = HTX_RASTER_BASE + offsetof(HTX_RASTER_Type, FIFO);
  size_t i = 0, answered = 0;
  uint64_t waited = 0;
  while (answered < words.size()) {
    q.valid = i < words.size();
    if (q.valid) q.wdata = words[i];
    bool rr = false, mr = false;
    port_->settle(q, PortRequest{}, &rr, &mr);
    PortResponse r, m;
    port_->rise(&r, &m);
    ++cycles_;
    if (q.valid && rr) ++i;
    if (r.rsp_valid) {
      if (r.rsp_err) throw std::runtime_error("rtl engine: a RASTER.FIFO write failed");
      ++answered;
      waited = 0;
    } else if (++waited > kRequestLimit) {
      throw std::runtime_error("rtl engine: RASTER.FIFO stopped taking words");
    }
  }
}

void GpuSim::wait_idle(uint64_t max_cycles) {
  const uint64_t start = cycles_;
  const uint32_t raster_status = HTX_RASTER_BASE + offsetof(HTX_RASTER_Type, STATUS);
  const uint32_t texture_status = HTX_TEXTURE_BASE + offsetof(HTX_TEXTURE_Type, STATUS);
  while ((read_reg(raster_status) & RASTER_STATUS_BUSY_Msk) || (read_reg(texture_status) & TEXTURE_STATUS_BUSY_Msk)) {
    if (cycles_ - start > max_cycles)
      throw std::runtime_error("rtl engine: the GPU did not go idle within " + std::to_string(max_cycles) +
                               " clocks");
  }
}

std::vector<uint32_t> GpuSim::read_words(uint32_t base, uint32_t n) {
  std::vector<uint32_t> out;
  out.reserve(n);
  uint32_t issued = 0;
  uint64_t waited = 0;
  while (out.size() < n) {
    PortRequest q;
    q.valid = issued < n;
    q.addr = base + 4 * issued;
    bool rr = false, mr = false;
    port_->settle(PortRequest{}, q, &rr, &mr);
    PortResponse r, m;
    port_->rise(&r, &m);
    ++cycles_;
    if (m.rsp_valid) {
      if (m.rsp_err) throw std::runtime_error("rtl engine: framebuffer read outside the memory");
      out.push_back(m.rdata);
      waited = 0;
    } else if (++waited > kRequestLimit) {
      throw std::runtime_error("rtl engine: framebuffer reads got no response");
    }
    if (q.valid && mr) ++issued;
  }
  return out;
}

std::vector<uint16_t> GpuSim::read_color(uint32_t n) {
  const std::vector<uint32_t> w = read_words(kColorWindow, (n + 1) / 2);
  std::vector<uint16_t> px(n);
  for (uint32_t i = 0; i < n; ++i) px[i] = static_cast<uint16_t>(w[i / 2] >> (16 * (i % 2)));
  return px;
}

std::vector<uint32_t> GpuSim::read_depth(uint32_t n) { return read_words(kDepthWindow, n); }

}  // namespace htx::rtl
