#include "htx/rtl/raster_sim.hpp"

#include <bit>
#include <cstddef>
#include <stdexcept>

#include "Vhtx_raster_full.h"
#include "Vhtx_raster_full___024root.h"
#include "Vhtx_raster_icebreaker.h"
#include "Vhtx_raster_icebreaker___024root.h"
#include "Vhtx_raster_icebreaker_untextured.h"
#include "Vhtx_raster_icebreaker_untextured___024root.h"
#include "htx/rtl/two_port_pins.hpp"
#include "htx_regs.h"
#include "verilated.h"

namespace htx::rtl {

// The Verilated configurations share every port name; this hides which one runs.
class RasterPort {
 public:
  virtual ~RasterPort() = default;
  // Drives both request ports, settles the logic with the clock low and returns the ready flags.
  virtual void settle(const PortRequest& reg, const PortRequest& mem, bool* reg_ready, bool* mem_ready) = 0;
  // Rising edge; returns the responses visible after it.
  virtual void rise(PortResponse* reg, PortResponse* mem) = 0;
  virtual void reset() = 0;
  std::vector<TexRequest>* record = nullptr;
};

namespace {

int64_t sext(uint64_t v, unsigned bits) {
  const uint64_t m = uint64_t{1} << (bits - 1);
  v &= (bits >= 64) ? ~uint64_t{0} : ((uint64_t{1} << bits) - 1);
  return static_cast<int64_t>((v ^ m) - m);
}

// The subsystem's pixel address width, $clog2(FbPixels + 1), which is the bit width of FbPixels:
// the low bits of a texture request's tag.
constexpr uint32_t kAddrMask = (uint32_t{1} << std::bit_width(RasterSim::kFbPixels)) - 1;

// The public loop-back signals of htx_raster_subsys (their names carry the top's name). Widths:
// CoordW, LocW, GradW of the configuration.
#define HTX_READ_REQUEST(SUB, R, COORDW, LOCW, GRADW)                                      \
  do {                                                                                     \
    auto* root = (R);                                                                      \
    if (!(root->SUB##__DOT__tex_req_valid &&                                \
          root->SUB##__DOT__tex_req_ready))                                 \
      return false;                                                                        \
    t->u = sext(root->SUB##__DOT__tex_req_u, COORDW);                       \
    t->v = sext(root->SUB##__DOT__tex_req_v, COORDW);                       \
    t->filter = root->SUB##__DOT__tex_req_filter;                           \
    t->wrap_u = root->SUB##__DOT__tex_req_wrap_u;                           \
    t->wrap_v = root->SUB##__DOT__tex_req_wrap_v;                           \
    t->slot = root->SUB##__DOT__tex_req_slot;                               \
    t->lod_q = root->SUB##__DOT__tex_req_lod_q;                             \
    for (int i = 0; i < 6; ++i)                                                            \
      t->lod_g[i] = sext(root->SUB##__DOT__tex_req_lod_g[i], GRADW);        \
    t->lod_shift = root->SUB##__DOT__tex_req_lod_shift;                     \
    t->lod_u = sext(root->SUB##__DOT__tex_req_lod_u, LOCW);                 \
    t->lod_v = sext(root->SUB##__DOT__tex_req_lod_v, LOCW);                 \
    t->addr = root->SUB##__DOT__tex_req_tag[0] & kAddrMask;                 \
    return true;                                                                           \
  } while (0)

bool read_request(Vhtx_raster_full& top, TexRequest* t) {
  HTX_READ_REQUEST(htx_raster_full__DOT__u_subsys, top.rootp, 48, 32, 24);
}
bool read_request(Vhtx_raster_icebreaker& top, TexRequest* t) {
  HTX_READ_REQUEST(htx_raster_icebreaker__DOT__u_subsys, top.rootp, 20, 23, 16);
}
bool read_request(Vhtx_raster_icebreaker_untextured& top, TexRequest* t) {
  HTX_READ_REQUEST(htx_raster_icebreaker__DOT__u_subsys, top.rootp, 20, 23, 16);
}
#undef HTX_READ_REQUEST

template <class V>
class VerilatedPort final : public RasterPort {
 public:
  VerilatedPort() : ctx_(std::make_unique<VerilatedContext>()), top_(std::make_unique<V>(ctx_.get())) {}
  ~VerilatedPort() override { top_->final(); }

  void settle(const PortRequest& r, const PortRequest& m, bool* reg_ready, bool* mem_ready) override {
    settle_ports(*top_, r, m, reg_ready, mem_ready);
    TexRequest t;
    if (record && read_request(*top_, &t)) record->push_back(t);
  }
  void rise(PortResponse* r, PortResponse* m) override { rise_ports(*top_, r, m); }
  void reset() override { reset_ports(*top_); }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
};

constexpr uint32_t kColorWindow = 0x30000000u;
constexpr uint32_t kDepthWindow = 0x30100000u;

}  // namespace

RasterSim::RasterSim(const std::string& config) {
  if (config == "full") {
    port_ = std::make_unique<VerilatedPort<Vhtx_raster_full>>();
  } else if (config == "icebreaker") {
    port_ = std::make_unique<VerilatedPort<Vhtx_raster_icebreaker>>();
  } else if (config == "icebreaker_untextured") {
    port_ = std::make_unique<VerilatedPort<Vhtx_raster_icebreaker_untextured>>();
  } else {
    throw std::invalid_argument("rtl engine: no Verilated raster for configuration '" + config +
                                "' (built: full, icebreaker, icebreaker_untextured)");
  }
  port_->reset();
}

RasterSim::~RasterSim() = default;

void RasterSim::record_requests(std::vector<TexRequest>* out) { port_->record = out; }

void RasterSim::tick() {
  bool rr = false, mr = false;
  port_->settle(PortRequest{}, PortRequest{}, &rr, &mr);
  PortResponse r, m;
  port_->rise(&r, &m);
  ++cycles_;
}

void RasterSim::idle(uint64_t n) {
  for (uint64_t i = 0; i < n; ++i) tick();
}

// One request on one port, held until accepted; its response is registered, so it is visible
// right after the accepting edge.
static PortResponse run_one(RasterPort& port, const PortRequest& req, bool on_mem, uint64_t& cycles) {
  // A request may wait while the unit draws a large triangle (a FIFO write behind it: a few million
  // clocks at most on the test scenes); one never taken is a deadlock, reported, not waited out.
  constexpr uint64_t kRequestWaitLimit = uint64_t{1} << 26;
  PortResponse r, m;
  for (uint64_t waited = 0;; ++waited) {
    bool rr = false, mr = false;
    port.settle(on_mem ? PortRequest{} : req, on_mem ? req : PortRequest{}, &rr, &mr);
    const bool accepted = on_mem ? mr : rr;
    port.rise(&r, &m);
    ++cycles;
    if (accepted) break;
    if (waited >= kRequestWaitLimit) throw std::runtime_error("rtl engine: bus request not taken in 2^26 clocks");
  }
  return on_mem ? m : r;
}

uint32_t RasterSim::read_reg(uint32_t offset) {
  uint32_t data = 0;
  reg_read(offset, &data);
  return data;
}

void RasterSim::write_reg(uint32_t offset, uint32_t value) { reg_write(offset, value); }

bool RasterSim::reg_read(uint32_t offset, uint32_t* data) {
  const PortRequest q = read_at(HTX_RASTER_BASE + offset);
  const PortResponse o = run_one(*port_, q, false, cycles_);
  *data = o.rdata;
  return o.rsp_err;
}

bool RasterSim::reg_write(uint32_t offset, uint32_t value) {
  const PortRequest q = write_at(HTX_RASTER_BASE + offset, value);
  return run_one(*port_, q, false, cycles_).rsp_err;
}

bool RasterSim::mem_read(uint32_t addr, uint32_t* data) {
  const PortRequest q = read_at(addr);
  const PortResponse o = run_one(*port_, q, true, cycles_);
  *data = o.rdata;
  return o.rsp_err;
}

bool RasterSim::mem_write(uint32_t addr, uint32_t data, uint8_t be) {
  const PortRequest q = write_at(addr, data, be);
  return run_one(*port_, q, true, cycles_).rsp_err;
}

void RasterSim::push_words(const std::vector<uint32_t>& words, unsigned gap_every, unsigned gap_cycles) {
  PortRequest q;
  q.valid = true;
  q.we = true;
  q.addr = HTX_RASTER_BASE + offsetof(HTX_RASTER_Type, FIFO);
  // A word may wait while the unit draws a whole large triangle (a few million clocks at most on
  // the test scenes); a unit that never takes it again is a deadlock, reported, not waited out.
  constexpr uint64_t kWordWaitLimit = uint64_t{1} << 23;
  size_t i = 0;
  size_t since_gap = 0;
  uint64_t waited = 0;
  while (i < words.size()) {
    q.wdata = words[i];
    bool rr = false, mr = false;
    port_->settle(q, PortRequest{}, &rr, &mr);
    PortResponse r, m;
    port_->rise(&r, &m);
    ++cycles_;
    if (!rr) {
      ++fifo_stall_cycles_;
      if (++waited > kWordWaitLimit)
        throw std::runtime_error("rtl engine: RASTER.FIFO took no word for " + std::to_string(kWordWaitLimit) +
                                 " clocks");
      continue;
    }
    waited = 0;
    ++i;
    if (gap_every && ++since_gap == gap_every) {
      since_gap = 0;
      idle(gap_cycles);
    }
  }
}

void RasterSim::wait_idle(uint64_t max_cycles) {
  const uint64_t start = cycles_;
  while (read_reg(offsetof(HTX_RASTER_Type, STATUS)) & RASTER_STATUS_BUSY_Msk) {
    if (cycles_ - start > max_cycles)
      throw std::runtime_error("rtl engine: the raster unit did not go idle within " + std::to_string(max_cycles) +
                               " clocks");
  }
}

namespace {

// Pipelined reads of n consecutive words from base: a new request every clock the port is ready.
std::vector<uint32_t> read_words(RasterPort& port, uint32_t base, uint32_t n, uint64_t& cycles) {
  std::vector<uint32_t> out;
  out.reserve(n);
  uint32_t issued = 0;
  while (out.size() < n) {
    PortRequest q;
    q.valid = issued < n;
    q.addr = base + 4 * issued;
    bool rr = false, mr = false;
    port.settle(PortRequest{}, q, &rr, &mr);
    PortResponse r, m;
    port.rise(&r, &m);
    ++cycles;
    if (m.rsp_valid) {
      if (m.rsp_err) throw std::runtime_error("rtl engine: framebuffer read outside the memory");
      out.push_back(m.rdata);
    }
    if (q.valid && mr) ++issued;
  }
  return out;
}

}  // namespace

std::vector<uint16_t> RasterSim::read_color(uint32_t n) {
  const std::vector<uint32_t> w = read_words(*port_, kColorWindow, (n + 1) / 2, cycles_);
  std::vector<uint16_t> px(n);
  for (uint32_t i = 0; i < n; ++i) px[i] = static_cast<uint16_t>(w[i / 2] >> (16 * (i % 2)));
  return px;
}

std::vector<uint32_t> RasterSim::read_depth(uint32_t n) { return read_words(*port_, kDepthWindow, n, cycles_); }

}  // namespace htx::rtl
