// The console firmware on the simulated SoC, run in a thread of htx with its UART on a
// pseudo-terminal: what `htx render --engine soc` talks to, as `--engine board` talks to a board's
// serial port (docs/engines.md). Only where the SoC harness is built (htx_soc_sim).
#pragma once

#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "htx/sim/serial_endpoint.hpp"
#include "htx/sim/soc_sim.hpp"

namespace htx {

class SocConsole {
 public:
  // Loads the ELF and starts the run. Throws std::runtime_error when the ELF cannot be loaded.
  explicit SocConsole(const std::string& elf_path);
  // Ends the run if it is still going (SimOptions::stop) and waits for its thread.
  ~SocConsole();
  SocConsole(const SocConsole&) = delete;
  SocConsole& operator=(const SocConsole&) = delete;

  // The pseudo-terminal the UART is on (a console::SerialPort opens it); gone once the run ends.
  const std::string& pty() const { return pty_; }
  // Waits up to `limit` for the run to end (the firmware exits after `quit`) and returns how it
  // ended. Throws std::runtime_error when it has not ended by then (it is stopped) or failed.
  sim::SimResult finish(std::chrono::milliseconds limit);
  // When the run has already ended (the firmware exited, or the CPU stopped retiring), how: "the
  // simulated SoC had stopped after N clocks: stuck (no instruction retired in ...)". The
  // pseudo-terminal closes as the run ends, so a client on it fails at once and can say why.
  std::optional<std::string> ended_early();

 private:
  std::string pty_;
  std::unique_ptr<sim::SerialEndpoint> uart_;
  std::atomic<bool> stop_{false};
  std::ostringstream putchar_;  // SYSCTRL.SIM_PUTCHAR output (the console firmware prints none)
  std::unique_ptr<sim::SocSim> soc_;
  std::promise<sim::SimResult> done_;
  std::future<sim::SimResult> result_;
  // result_'s value or error once taken (a future gives it once).
  std::optional<sim::SimResult> ended_;
  std::exception_ptr failure_;
  std::thread thread_;

  // Takes the run's result into ended_ or failure_ if it comes within `wait` (at once when it
  // was taken before); false when the run is still going.
  bool take_result(std::chrono::milliseconds wait);
};

}  // namespace htx
