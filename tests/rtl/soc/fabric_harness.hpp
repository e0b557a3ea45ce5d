// Drives htx_soc_fabric (the SoC without its CPU) from C++: two bus masters standing in for the
// CPU's instruction and data ports, each with a queue of requests, collecting in-order responses.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

class Vhtx_soc_fabric;

namespace htx::test {

struct BusReq {
  uint32_t addr = 0;
  bool we = false;
  uint8_t be = 0xF;
  uint32_t wdata = 0;
};

struct BusRsp {
  uint32_t rdata = 0;
  bool err = false;
  uint64_t cycle = 0;  // clock in which the response was seen
};

// The video scan-out's pins after a clock (htx_video: two clocks behind its counters).
struct VideoPins {
  bool de = false, hsync_n = true, vsync_n = true;
  uint32_t rgb = 0;  // RGB888
};

struct BusMaster {
  std::deque<BusReq> pending;      // not yet accepted
  std::deque<BusReq> outstanding;  // accepted, response due
  std::vector<BusRsp> responses;   // in arrival order
  uint64_t accepted = 0;
};

class FabricHarness {
 public:
  // stall_seed: random wait states on every slave when set (htx_bus_stall).
  explicit FabricHarness(bool stalls = false, uint32_t stall_seed = 0);
  ~FabricHarness();

  BusMaster ibus, dbus;
  bool uart_rx = true;  // level driven on the UART RX pin
  bool uart_tx() const;
  bool timer_irq() const;
  bool sim_exit_strobe() const;
  uint8_t sim_exit_code() const;
  VideoPins video() const;
  uint64_t cycle() const { return cycle_; }

  void step();  // one clock
  // Steps until both masters have nothing pending or outstanding; false if `limit` clocks pass.
  bool drain(uint64_t limit = 100000);
  // Single data-bus access, waited for.
  BusRsp read(uint32_t addr);
  BusRsp write(uint32_t addr, uint32_t data, uint8_t be = 0xF);

 private:
  void drive(BusMaster& m, bool is_ibus);
  std::unique_ptr<Vhtx_soc_fabric> top_;
  uint64_t cycle_ = 0;
};

}  // namespace htx::test
