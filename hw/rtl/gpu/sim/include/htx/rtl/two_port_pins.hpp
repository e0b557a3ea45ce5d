// The two slave ports every Verilated GPU, raster and texture top has under the same names
// (reg_req_* and mem_req_* in, reg_rsp_* and mem_rsp_* out, clk_i, rst_ni): one request each,
// settled with the clock low; a rising edge and the responses after it; reset. Used by the GPU's
// and the raster unit's simulators (gpu_sim.cpp, raster_sim.cpp) for any of their tops, and by the
// texture unit's test harness for its request pins.
#pragma once

#include <cstdint>

namespace htx::rtl {

struct PortRequest {
  bool valid = false, we = false;
  uint32_t addr = 0, wdata = 0;
  uint8_t be = 0xF;
};
inline PortRequest read_at(uint32_t addr) {
  PortRequest q;
  q.valid = true;
  q.addr = addr;
  return q;
}
inline PortRequest write_at(uint32_t addr, uint32_t data, uint8_t be = 0xF) {
  PortRequest q = read_at(addr);
  q.we = true;
  q.wdata = data;
  q.be = be;
  return q;
}

struct PortResponse {
  bool rsp_valid = false, rsp_err = false;
  uint32_t rdata = 0;
};

// Sets both request ports' pins (no evaluation).
template <class V>
void drive_requests(V& top, const PortRequest& r, const PortRequest& m) {
  top.reg_req_valid_i = r.valid;
  top.reg_req_addr_i = r.addr;
  top.reg_req_we_i = r.we;
  top.reg_req_be_i = r.be;
  top.reg_req_wdata_i = r.wdata;
  top.mem_req_valid_i = m.valid;
  top.mem_req_addr_i = m.addr;
  top.mem_req_we_i = m.we;
  top.mem_req_be_i = m.be;
  top.mem_req_wdata_i = m.wdata;
}

// Drives both request ports, settles the logic with the clock low and returns the ready flags.
template <class V>
void settle_ports(V& top, const PortRequest& r, const PortRequest& m, bool* reg_ready, bool* mem_ready) {
  drive_requests(top, r, m);
  top.clk_i = 0;
  top.eval();
  *reg_ready = top.reg_req_ready_o;
  *mem_ready = top.mem_req_ready_o;
}

// Rising edge; the responses visible after it.
template <class V>
void rise_ports(V& top, PortResponse* r, PortResponse* m) {
  top.clk_i = 1;
  top.eval();
  r->rsp_valid = top.reg_rsp_valid_o;
  r->rsp_err = top.reg_rsp_err_o;
  r->rdata = top.reg_rsp_rdata_o;
  m->rsp_valid = top.mem_rsp_valid_o;
  m->rsp_err = top.mem_rsp_err_o;
  m->rdata = top.mem_rsp_rdata_o;
}

// Both ports idle, reset held over two clocks, then released.
template <class V>
void reset_ports(V& top) {
  top.reg_req_valid_i = 0;
  top.mem_req_valid_i = 0;
  top.rst_ni = 0;
  top.clk_i = 0;
  top.eval();
  for (int i = 0; i < 2; ++i) {
    top.clk_i = 1;
    top.eval();
    top.clk_i = 0;
    top.eval();
  }
  top.rst_ni = 1;
  top.eval();
}

}  // namespace htx::rtl
