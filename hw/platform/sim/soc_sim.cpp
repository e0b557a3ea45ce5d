#include "htx/sim/soc_sim.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "Vhtx_soc_sim_top.h"
#include "Vhtx_soc_sim_top___024root.h"
#include "htx/sim/uart_line.hpp"
#include "htx_regs.h"
#include "verilated.h"
#include "verilated_fst_c.h"

namespace htx::sim {
namespace {
// How often (in clocks) the host endpoint is polled for input: a syscall per poll, and far shorter
// than one serial bit time would need (104 clocks at 115200 baud).
constexpr uint64_t kPollInterval = 256;
// A run in which no instruction retires for this many clocks has stopped for good: the CPU traps
// in a loop (every trap handler retires instructions; one at an illegal address does not) or waits
// on a bus access that never completes. No access of the SoC waits near this long: the longest,
// a vertex write into a full raster FIFO, waits for a few triangles' pixels (some 10^5 clocks).
constexpr uint64_t kStuckClocks = uint64_t{1} << 23;
// The UART's divisor at reset (hw/regs/uart.json), where the host's end of the line starts; from
// the first clock on it follows the register.
constexpr uint32_t kUartResetDivisor = UART_CTRL_DIVISOR_Reset;
// A script's input is over when the firmware has read the empty receiver this many times in a row,
// each within kWaitPollGap clocks of the last, sending nothing: a loop waiting for a byte (the
// console polls every few clocks), not a check between frames (`spin` polls once a frame).
constexpr uint32_t kWaitPolls = 1000;
constexpr uint64_t kWaitPollGap = 1000;

std::string hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}
}  // namespace

const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::Exit: return "exit";
    case StopReason::ToHost: return "tohost";
    case StopReason::CycleLimit: return "cycle_limit";
    case StopReason::InputEnded: return "input_ended";
    case StopReason::Stopped: return "stopped";
    case StopReason::Stuck: return "stuck";
  }
  return "?";
}

struct SocSim::Impl {
  SimOptions opt;
  SerialEndpoint* uart;
  std::ostream& console;
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<Vhtx_soc_sim_top> top;
  std::unique_ptr<VerilatedFstC> trace;
  UartLineDecoder rx_decoder;   // the SoC's TX pin
  UartLineEncoder tx_encoder;   // drives the SoC's RX pin
  std::optional<uint32_t> tohost_word;
  std::optional<VideoCapture> screen;
  uint64_t time = 0;

  Impl(const SimOptions& o, SerialEndpoint* u, std::ostream& c)
      : opt(o), uart(u), console(c), ctx(std::make_unique<VerilatedContext>()),
        rx_decoder(kUartResetDivisor), tx_encoder(kUartResetDivisor) {}

  auto& ram() { return top->rootp->htx_soc_sim_top__DOT__u_soc__DOT__u_fabric__DOT__u_ram__DOT__mem_q; }
  // The UART's clocks per bit (its divisor, at least 4), which the host's end of the line follows.
  uint32_t uart_divisor() const { return top->rootp->htx_soc_sim_top__DOT__u_soc__DOT__u_fabric__DOT__u_uart__DOT__divisor; }
  bool uart_rx_full() const { return top->rootp->htx_soc_sim_top__DOT__u_soc__DOT__u_fabric__DOT__u_uart__DOT__rx_full; }
  bool uart_rx_empty_read() const {
    return top->rootp->htx_soc_sim_top__DOT__u_soc__DOT__u_fabric__DOT__u_uart__DOT__rx_empty_read;
  }
  // The framebuffer's colour memory, two pixels a word (the lower pixel in bits 15:0).
  auto& fb_color() {
    return top->rootp
        ->htx_soc_sim_top__DOT__u_soc__DOT__u_fabric__DOT__g_gpu__DOT__u_gpu__DOT__u_subsys__DOT__u_fb__DOT__u_color__DOT__g_behav__DOT__mem_q;
  }

  uint32_t fb_draw_page() {
    return top->rootp->htx_soc_sim_top__DOT__u_soc__DOT__u_fabric__DOT__g_gpu__DOT__u_gpu__DOT__u_subsys__DOT__u_raster__DOT__u_regs__DOT__draw_page_q;
  }

  void half_cycle(bool clk) {
    top->clk_i = clk;
    top->eval();
    if (trace) trace->dump(time);
    time += 5;
  }
  void cycle() {
    half_cycle(false);
    half_cycle(true);
  }
};

std::vector<uint32_t> check_runnable(const ElfImage& elf) {
  const std::vector<uint32_t> words = ram_words(elf, SocSim::kRamBytes);
  if (elf.entry != SocSim::kResetVector)
    throw std::runtime_error("entry point " + hex(elf.entry) + " is not the SoC's reset vector " +
                             hex(SocSim::kResetVector) + " (link the firmware for RAM at 0)");
  if (auto t = elf.symbol("tohost")) {
    if (*t % 4 != 0 || *t >= SocSim::kRamBytes)
      throw std::runtime_error("symbol tohost (" + hex(*t) + ") is not a RAM word");
    if (words[*t / 4] != 0)
      throw std::runtime_error("symbol tohost (" + hex(*t) + ") holds " + hex(words[*t / 4]) +
                               " in the image: the run would end in its first clock");
  }
  return words;
}

SocSim::SocSim(const ElfImage& elf, const SimOptions& options, SerialEndpoint* uart,
               std::ostream& console)
    : impl_(std::make_unique<Impl>(options, uart, console)) {
  const std::vector<uint32_t> words = check_runnable(elf);  // before the trace file is opened
  Impl& s = *impl_;
  if (!options.trace_path.empty()) s.ctx->traceEverOn(true);
  s.top = std::make_unique<Vhtx_soc_sim_top>(s.ctx.get(), "soc");
  if (options.capture_screen) s.screen.emplace();
  if (!options.trace_path.empty()) {
    s.trace = std::make_unique<VerilatedFstC>();
    s.top->trace(s.trace.get(), 99);
    s.trace->open(options.trace_path.c_str());
    if (!s.trace->isOpen()) throw std::runtime_error(options.trace_path + ": cannot open trace file");
  }

  auto& ram = s.ram();
  for (uint32_t i = 0; i < kRamBytes / 4; ++i) ram[i] = words[i];
  if (auto t = elf.symbol("tohost")) s.tohost_word = *t / 4;

  s.top->rst_ni = 0;
  s.top->uart_rx_i = 1;
  s.top->rootp->htx_soc_sim_top__DOT__stall_en = options.stall_seed.has_value();
  s.top->rootp->htx_soc_sim_top__DOT__stall_seed = options.stall_seed.value_or(0);
  s.top->rootp->htx_soc_sim_top__DOT__u_soc__DOT__u_fabric__DOT__g_gpu__DOT__g_sim_gpu_gate__DOT__gate_allow =
      options.gpu_clock_gate ? 1 : 0;
  for (int i = 0; i < 4; ++i) s.cycle();
  s.top->rst_ni = 1;
}

uint64_t CpuProfile::total() const {
  uint64_t sum = 0;
  for (uint64_t c : counts) sum += c;
  return sum;
}

SocSim::~SocSim() {
  if (impl_ && impl_->trace) impl_->trace->close();
  if (impl_ && impl_->top) impl_->top->final();
}

SimResult SocSim::run() {
  Impl& s = *impl_;
  SimResult res;
  const auto t0 = std::chrono::steady_clock::now();
  uint8_t inbuf[256];
  size_t script_at = 0, script_len = 0;  // paced input: inbuf[script_at, script_len) not yet sent
  auto& ram = s.ram();
  uint64_t c = 0;
  bool done = false;
  // The script has ended and every byte of it is in the UART (input_over); then the firmware's
  // reads of the empty receiver are counted (waiting_polls, the last at last_empty_read). An empty
  // stdin (/dev/null, as under a test runner) is no script: that run ends as it did before.
  bool input_over = false, script_sent = false;
  uint32_t waiting_polls = 0;
  uint64_t last_empty_read = 0;
  if (s.opt.profile_pcs) res.pcs.emplace(kRamBytes);
  uint32_t last_pc = 0;
  uint64_t last_instret = s.top->instret_o, last_retire = 0;
  while (!done && c < s.opt.max_cycles) {
    if (res.pcs) {
      // This clock's state, settled by the last edge's eval (e_done is combinational).
      const bool live = s.top->cpu_e_valid_o, completes = live && s.top->cpu_e_done_o;
      if (live) {
        last_pc = s.top->cpu_e_pc_o;
        res.pcs->live(last_pc, c);
      }
      res.pcs->charge(last_pc, completes);
      if (completes && last_pc < kRamBytes) res.pcs->completed(last_pc, ram[last_pc / 4]);
    }
    // The host's end of the line runs at the rate the firmware set (the console's `baud` command
    // changes it while the line is quiet; a user's terminal is set to match).
    if (const uint32_t cpb = s.uart_divisor(); cpb != s.rx_decoder.clocks_per_bit()) {
      s.rx_decoder.set_clocks_per_bit(cpb);
      s.tx_encoder.set_clocks_per_bit(cpb);
    }
    s.top->uart_rx_i = s.tx_encoder.step();
    s.cycle();
    ++c;

    if (auto byte = s.rx_decoder.step(s.top->uart_tx_o)) {
      if (s.uart) s.uart->write(&*byte, 1);
      waiting_polls = 0;
    }
    if (input_over && s.uart_rx_empty_read()) {
      waiting_polls = c - last_empty_read <= kWaitPollGap ? waiting_polls + 1 : 1;
      last_empty_read = c;
      if (waiting_polls >= kWaitPolls) {
        // It waits for input that cannot come: the run ends, as a shell does at its script's end.
        res.reason = StopReason::InputEnded;
        done = true;
      }
    }
    if (s.top->sim_putchar_o) s.console.put(static_cast<char>(s.top->sim_char_o));
    if (s.screen && s.screen->clock(s.top->video_de_o, s.top->video_vsync_no, s.top->video_rgb_o) &&
        s.opt.on_screen_frame)
      s.opt.on_screen_frame(*s.screen);
    if (s.top->sim_exit_o) {
      res.reason = StopReason::Exit;
      res.exit_code = s.top->sim_exit_code_o;
      done = true;
    }
    if (s.tohost_word) {
      const uint32_t v = ram[*s.tohost_word];
      if (v != 0) {
        res.reason = StopReason::ToHost;
        // riscv-tests: (code << 1) | 1 ends the test; even values are syscall requests, which
        // this harness does not serve, so they end the run as a failure.
        res.exit_code = (v & 1u) ? static_cast<int>(v >> 1) : 1;
        if (!(v & 1u)) res.note = "tohost = " + hex(v) + " is a syscall request, which is not supported";
        done = true;
      }
    }
    if (!done && c % kPollInterval == 0) {
      if (s.top->instret_o != last_instret) {
        last_instret = s.top->instret_o;
        last_retire = c;
      } else if (c - last_retire >= kStuckClocks) {
        res.reason = StopReason::Stuck;
        res.note = "no instruction retired in " + std::to_string(c - last_retire) +
                   " cycles (execute stage at pc " + hex(s.top->cpu_e_pc_o) +
                   "): the CPU traps in a loop, or waits on a bus access that never completes";
        done = true;
      }
      if (!done && s.opt.stop && s.opt.stop->load(std::memory_order_relaxed)) {
        res.reason = StopReason::Stopped;
        done = true;
      }
    }
    if (s.uart && c % kPollInterval == 0) {
      if (!s.uart->paced()) {
        // A person or a serial program: at the line's rate, as on a board (a burst can overrun
        // the FIFO, which the firmware reports).
        if (s.tx_encoder.queued() < 16) {
          const size_t n = s.uart->read(inbuf, sizeof inbuf);
          for (size_t i = 0; i < n; ++i) s.tx_encoder.push(inbuf[i]);
        }
      } else if (s.tx_encoder.idle() && !s.uart_rx_full()) {
        // A script: a byte at a time, each once the last is in the FIFO and only while the FIFO
        // has room for it (so a byte is never sent into a full FIFO, whatever its depth).
        if (script_at == script_len) {
          script_len = s.uart->read(inbuf, sizeof inbuf);
          script_at = 0;
        }
        if (script_at < script_len) {
          s.tx_encoder.push(inbuf[script_at++]);
          script_sent = true;
        }
        input_over = script_sent && script_at == script_len && s.uart->ended();
      }
      if (c % (kPollInterval * 1024) == 0) s.uart->flush();
    }
  }
  if (s.uart) s.uart->flush();
  s.console.flush();
  if (res.pcs) res.pcs->finish(c);
  res.cycles = c;
  res.instret = s.top->instret_o;
  for (size_t i = 0; i < CpuProfile::kCauses; ++i) {
    res.profile.counts[i] = s.top->rootp->htx_soc_sim_top__DOT__u_cpu_profile__DOT__count_q[i];
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

std::vector<uint32_t> SocSim::read_words(uint32_t begin, uint32_t end) const {
  if (begin % 4 != 0 || end % 4 != 0 || begin > end || end > kRamBytes) {
    throw std::runtime_error("memory range [" + hex(begin) + ", " + hex(end) +
                             ") is not a word-aligned range inside RAM");
  }
  std::vector<uint32_t> out;
  auto& ram = impl_->ram();
  for (uint32_t a = begin; a < end; a += 4) out.push_back(ram[a / 4]);
  return out;
}

std::vector<uint16_t> SocSim::read_frame(uint32_t width, uint32_t height) const {
  if (width == 0 || height == 0 || uint64_t{width} * height > kFbPixels) {
    throw std::runtime_error("frame of " + std::to_string(width) + "x" + std::to_string(height) +
                             " pixels does not fit the framebuffer of " + std::to_string(kFbPixels) + " pixels");
  }
  auto& mem = impl_->fb_color();
  // The colour page the raster unit draws into (FB_PAGE.DRAW), which holds the frame drawn last.
  const size_t first = size_t{impl_->fb_draw_page()} * kFbPixels;
  std::vector<uint16_t> out(size_t{width} * height);
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<uint16_t>(mem[(first + i) / 2] >> (16 * ((first + i) % 2)));
  return out;
}

const VideoCapture* SocSim::screen() const { return impl_->screen ? &*impl_->screen : nullptr; }

}  // namespace htx::sim
