// The whole SoC in Verilator, driven clock by clock: loads an ELF into RAM, releases reset and runs
// until the firmware exits (SYSCTRL.SIM_EXIT, or the `tohost` convention of RISC-V tests) or the
// cycle limit. The UART's serial line is encoded/decoded bit by bit and connected to a host endpoint.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "htx/sim/elf_image.hpp"
#include "htx/sim/function_profile.hpp"
#include "htx/sim/serial_endpoint.hpp"
#include "htx/sim/video_capture.hpp"

namespace htx::sim {

struct SimOptions {
  uint64_t max_cycles = 1'000'000'000;
  std::optional<uint32_t> stall_seed;  // random wait states on every bus slave
  std::string trace_path;              // FST waveform; empty = none
  // Stop the GPU's clock while it is idle (htx_soc_fabric, Sim only): the same results, several
  // times faster. false runs it free, to check that claim.
  bool gpu_clock_gate = true;
  // Watch the video scan-out's pins and keep the last whole frame it showed (screen()).
  bool capture_screen = false;
  // With capture_screen: called with the monitor each time a whole frame has been shown.
  std::function<void(const VideoCapture&)> on_screen_frame;
  // Charge every clock to an instruction address (SimResult::pcs): the instruction in execute, or
  // while execute is empty the last one it held (a bubble's clocks go to the instruction before it).
  bool profile_pcs = false;
  // Set by another thread to end the run (StopReason::Stopped), looked at every few hundred
  // clocks: how a host tool that runs the SoC in a thread of its own ends it when it gives up.
  const std::atomic<bool>* stop = nullptr;
};

// InputEnded: a script's input ended and the firmware then waited for more (SocSim::run).
// Stopped: SimOptions::stop was set. Stuck: no instruction retired for 2^23 clocks (a trap loop,
// or a bus access that never completes; SimResult::note says where).
enum class StopReason { Exit, ToHost, CycleLimit, InputEnded, Stopped, Stuck };

// Where the CPU's clocks went (hw/platform/sim/htx_cpu_profile.sv): every clock after reset is
// charged to one cause, judged at the execute stage, so the counts add up to the clocks run.
struct CpuProfile {
  static constexpr size_t kCauses = 9;
  // In the RTL's order (htx_cpu_profile's cause_e).
  static constexpr std::array<const char*, kCauses> kNames = {
      "execute", "data_bus", "mul_div", "csr_order", "load_use", "late_result", "redirect", "jump", "fetch"};
  std::array<uint64_t, kCauses> counts{};
  uint64_t total() const;
};

struct SimResult {
  StopReason reason = StopReason::CycleLimit;
  int exit_code = 0;      // firmware's status (SIM_EXIT code, or tohost >> 1)
  std::string note;       // how the run ended, when a status alone does not say (a tohost syscall)
  uint64_t cycles = 0;    // clocks after reset was released
  uint64_t instret = 0;   // instructions retired (the CPU's minstret)
  double seconds = 0.0;   // host wall time of the run
  CpuProfile profile;
  std::optional<PcProfile> pcs;  // with SimOptions::profile_pcs
};

const char* to_string(StopReason r);

// Checks that `elf` can run on the SoC, so that a tool can refuse it before it opens anything:
// every segment in RAM, the entry point at the reset vector (the core starts there, whatever the
// ELF says), and a `tohost` symbol, if there is one, on a RAM word that is zero in the image (a
// non-zero one would end the run in its first clock). Throws std::runtime_error saying which;
// returns the RAM's words as loaded.
std::vector<uint32_t> check_runnable(const ElfImage& elf);

class SocSim {
 public:
  static constexpr uint32_t kClockHz = 12'000'000;  // htx_soc_sim_top's ClockHz (SYSCTRL.CLOCK_HZ)
  static constexpr uint32_t kRamBytes = 131072;  // htx_soc_sim_top's RamBytes
  static constexpr uint32_t kResetVector = 0;    // htx_soc's ResetVector (docs/soc.md)
  static constexpr uint32_t kFbPixels = 19200;  // the GPU's framebuffer (htx_soc_fabric's FbPixels)

  // Throws std::runtime_error if check_runnable(elf) does, or the trace cannot be opened.
  // `uart` may be null (the RX line stays idle, TX bytes are dropped); SIM_PUTCHAR goes to `console`.
  SocSim(const ElfImage& elf, const SimOptions& options, SerialEndpoint* uart, std::ostream& console);
  ~SocSim();
  SocSim(const SocSim&) = delete;
  SocSim& operator=(const SocSim&) = delete;

  SimResult run();
  // RAM words in [begin, end) (byte addresses, 4-aligned); throws if outside RAM.
  std::vector<uint32_t> read_words(uint32_t begin, uint32_t end) const;
  // The colour page the raster unit draws into (FB_PAGE.DRAW: the frame drawn last) as it wrote it:
  // width x height RGB565 pixels with stride `width`, pixel i at the page's half-word i
  // (docs/contracts.md). Throws if width * height exceeds kFbPixels, the pixels of a page.
  std::vector<uint16_t> read_frame(uint32_t width, uint32_t height) const;
  // The video scan-out as a monitor saw it (SimOptions::capture_screen; null without it).
  const VideoCapture* screen() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace htx::sim
