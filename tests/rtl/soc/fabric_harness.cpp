#include "fabric_harness.hpp"

#include <stdexcept>

#include "Vhtx_soc_fabric.h"

namespace htx::test {

FabricHarness::FabricHarness(bool stalls, uint32_t stall_seed) : top_(std::make_unique<Vhtx_soc_fabric>()) {
  top_->stall_en_i = stalls;
  top_->stall_seed_i = stall_seed;
  top_->uart_rx_i = 1;
  top_->rst_ni = 0;
  for (int i = 0; i < 3; ++i) {
    top_->clk_i = 0;
    top_->eval();
    top_->clk_i = 1;
    top_->eval();
  }
  top_->rst_ni = 1;
}

FabricHarness::~FabricHarness() { top_->final(); }

bool FabricHarness::uart_tx() const { return top_->uart_tx_o; }
bool FabricHarness::timer_irq() const { return top_->timer_irq_o; }
VideoPins FabricHarness::video() const {
  return {top_->video_de_o != 0, top_->video_hsync_no != 0, top_->video_vsync_no != 0, top_->video_rgb_o};
}
bool FabricHarness::sim_exit_strobe() const { return top_->sim_exit_o; }
uint8_t FabricHarness::sim_exit_code() const { return top_->sim_exit_code_o; }

void FabricHarness::drive(BusMaster& m, bool is_ibus) {
  const bool valid = !m.pending.empty();
  const BusReq r = valid ? m.pending.front() : BusReq{};
  if (is_ibus) {
    top_->ibus_req_valid_i = valid;
    top_->ibus_req_addr_i = r.addr;
    top_->ibus_req_we_i = r.we;
    top_->ibus_req_be_i = r.be;
    top_->ibus_req_wdata_i = r.wdata;
  } else {
    top_->dbus_req_valid_i = valid;
    top_->dbus_req_addr_i = r.addr;
    top_->dbus_req_we_i = r.we;
    top_->dbus_req_be_i = r.be;
    top_->dbus_req_wdata_i = r.wdata;
  }
}

void FabricHarness::step() {
  drive(ibus, true);
  drive(dbus, false);
  top_->uart_rx_i = uart_rx;
  top_->clk_i = 0;
  top_->eval();  // settle the combinational ready and response paths for this clock
  struct Sample {
    BusMaster& m;
    bool valid, ready, rsp_valid, rsp_err;
    uint32_t rsp_rdata;
  } samples[2] = {
      {ibus, static_cast<bool>(top_->ibus_req_valid_i), static_cast<bool>(top_->ibus_req_ready_o),
       static_cast<bool>(top_->ibus_rsp_valid_o), static_cast<bool>(top_->ibus_rsp_err_o), top_->ibus_rsp_rdata_o},
      {dbus, static_cast<bool>(top_->dbus_req_valid_i), static_cast<bool>(top_->dbus_req_ready_o),
       static_cast<bool>(top_->dbus_rsp_valid_o), static_cast<bool>(top_->dbus_rsp_err_o), top_->dbus_rsp_rdata_o},
  };
  for (auto& s : samples) {
    if (s.rsp_valid) {
      if (s.m.outstanding.empty()) throw std::runtime_error("bus response without an outstanding request");
      s.m.outstanding.pop_front();
      s.m.responses.push_back({s.rsp_rdata, s.rsp_err, cycle_});
    }
    if (s.valid && s.ready) {
      s.m.outstanding.push_back(s.m.pending.front());
      s.m.pending.pop_front();
      ++s.m.accepted;
    }
  }
  top_->clk_i = 1;
  top_->eval();
  ++cycle_;
}

bool FabricHarness::drain(uint64_t limit) {
  for (uint64_t i = 0; i < limit; ++i) {
    if (ibus.pending.empty() && ibus.outstanding.empty() && dbus.pending.empty() && dbus.outstanding.empty()) {
      return true;
    }
    step();
  }
  return false;
}

BusRsp FabricHarness::read(uint32_t addr) {
  const size_t before = dbus.responses.size();
  dbus.pending.push_back({addr, false, 0xF, 0});
  if (!drain() || dbus.responses.size() != before + 1) throw std::runtime_error("read did not complete");
  return dbus.responses.back();
}

BusRsp FabricHarness::write(uint32_t addr, uint32_t data, uint8_t be) {
  const size_t before = dbus.responses.size();
  dbus.pending.push_back({addr, true, be, data});
  if (!drain() || dbus.responses.size() != before + 1) throw std::runtime_error("write did not complete");
  return dbus.responses.back();
}

}  // namespace htx::test
