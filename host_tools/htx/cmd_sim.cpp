// htx sim: run a firmware ELF on the whole SoC in Verilator.
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "frame_size.hpp"

#if __has_include("htx/sim/soc_sim.hpp")
#define HTX_HAVE_SOC_SIM 1
#include "htx/model/file_out.hpp"
#include "htx/model/image_io.hpp"
#include "htx/sim/elf_image.hpp"
#include "htx/sim/frame_crc.hpp"
#include "htx/sim/function_profile.hpp"
#include "htx/sim/serial_endpoint.hpp"
#include "htx/sim/soc_sim.hpp"
#include "output_path.hpp"
#else
#define HTX_HAVE_SOC_SIM 0  // configured with -DHTX_BUILD_RTL=OFF: no Verilated SoC
#endif

namespace htx {
namespace {

// Exit status when the cycle limit ends the run (as timeout(1) does); firmware should not use it.
constexpr int kCycleLimitStatus = 124;

struct SimArgs {
  std::string elf;
  std::string uart = "stdio";
  uint64_t max_cycles = 1'000'000'000;
  std::string signature;
  std::string trace;
  std::optional<uint32_t> stall_seed;
  bool json = false;
  bool profile = false;
  bool hotspots = false;
  bool no_gpu_gate = false;
  std::string frame;                // PNG of the colour window at exit
  std::string frame_size = "160x120";
  std::string screen;               // PNG of the last whole frame the video scan-out showed
  std::string screen_frames;        // directory: every picture the screen showed, once each
};

// "WxH" -> (W, H); both 1..4096.
std::pair<uint32_t, uint32_t> parse_frame_size(const std::string& s) {
  const auto size = parse_wxh(s, 4096);
  if (!size) throw std::runtime_error("--frame-size '" + s + "' is not WIDTHxHEIGHT with sides 1..4096");
  return *size;
}

#if HTX_HAVE_SOC_SIM
// One line per cause, with its share of the clocks (stderr, beside the summary).
void print_profile(const sim::CpuProfile& p) {
  const uint64_t total = p.total();
  std::fprintf(stderr, "htx sim: where the CPU's %llu clocks went (judged at execute):\n",
               static_cast<unsigned long long>(total));
  for (size_t i = 0; i < sim::CpuProfile::kCauses; ++i) {
    const double share = total ? 100.0 * static_cast<double>(p.counts[i]) / static_cast<double>(total) : 0.0;
    std::fprintf(stderr, "  %-12s %12llu  %5.1f %%\n", sim::CpuProfile::kNames[i],
                 static_cast<unsigned long long>(p.counts[i]), share);
  }
}

// The functions that took the most clocks, one line each (stderr, beside the summary); JSON has them all.
constexpr size_t kHotspotLines = 20;

void print_hotspots(const std::vector<sim::FunctionCost>& costs, uint64_t total) {
  auto share = [total](uint64_t n) {
    return total ? 100.0 * static_cast<double>(n) / static_cast<double>(total) : 0.0;
  };
  std::fprintf(stderr,
               "htx sim: where the CPU's %llu clocks went by function (an instruction's clocks at execute, a "
               "bubble's to the instruction before it; inclusive: from a call to its return):\n"
               "        clocks      %%     inclusive      %%      calls  instructions    CPI  function\n",
               static_cast<unsigned long long>(total));
  for (size_t i = 0; i < costs.size() && i < kHotspotLines; ++i) {
    const sim::FunctionCost& c = costs[i];
    char inclusive[40] = "             -       -";
    if (c.calls)
      std::snprintf(inclusive, sizeof inclusive, "%14llu  %5.1f", static_cast<unsigned long long>(c.inclusive),
                    share(c.inclusive));
    char calls[24] = "          -";
    if (c.calls) std::snprintf(calls, sizeof calls, "%11llu", static_cast<unsigned long long>(c.calls));
    char cpi[16] = "      -";
    if (c.instructions)
      std::snprintf(cpi, sizeof cpi, "%7.2f", static_cast<double>(c.cycles) / static_cast<double>(c.instructions));
    std::fprintf(stderr, "  %12llu  %5.1f%s %s  %12llu %s  %s\n", static_cast<unsigned long long>(c.cycles),
                 share(c.cycles), inclusive, calls, static_cast<unsigned long long>(c.instructions), cpi,
                 c.name.c_str());
  }
  if (costs.size() > kHotspotLines) {
    uint64_t rest = 0;
    for (size_t i = kHotspotLines; i < costs.size(); ++i) rest += costs[i].cycles;
    std::fprintf(stderr, "  %12llu  %5.1f  (%zu more functions; --json lists them all, with their callers)\n",
                 static_cast<unsigned long long>(rest), share(rest), costs.size() - kHotspotLines);
  }
}

// The words from begin_signature to end_signature: found and checked before the run, so that an
// ELF without them, or with a range the harness cannot read, is refused then.
struct SignatureRange {
  uint32_t begin = 0, end = 0;
};
SignatureRange signature_range(const sim::ElfImage& elf, const std::string& elf_path) {
  const auto begin = elf.symbol("begin_signature");
  const auto end = elf.symbol("end_signature");
  if (!begin || !end) throw std::runtime_error(elf_path + ": the ELF has no begin_signature/end_signature symbols");
  if (*begin % 4 != 0 || *end % 4 != 0 || *begin > *end || *end > sim::SocSim::kRamBytes) {
    char range[64];
    std::snprintf(range, sizeof range, "[0x%08x, 0x%08x)", *begin, *end);
    throw std::runtime_error(elf_path + ": begin_signature/end_signature " + range +
                             " is not a word-aligned range inside RAM");
  }
  return {*begin, *end};
}

void write_signature(const sim::SocSim& soc, SignatureRange range, const std::string& path) {
  const auto words = soc.read_words(range.begin, range.end);
  std::string text;
  for (uint32_t w : words) {
    char line[16];
    std::snprintf(line, sizeof line, "%08x\n", w);
    text += line;
  }
  write_file(path, text);
}
#endif

#if HTX_HAVE_SOC_SIM
// The last whole frame the video scan-out showed, as a monitor would show it.
Image image_of_screen(const sim::VideoCapture& screen) {
  return image_from_rgb888(static_cast<int>(screen.width()), static_cast<int>(screen.height()), screen.last_frame());
}

void write_screen(const sim::VideoCapture& screen, const std::string& path) {
  if (screen.frames() == 0) {
    throw std::runtime_error(path +
                             ": the run ended before the video scan-out had shown a whole frame (the first ends "
                             "after 420,000 clocks); not written");
  }
  write_png(path, image_of_screen(screen));
}

// Every picture the screen showed, once each: a whole frame equal to the one written before it
// is skipped, so a still screen writes one file and each flip of the frame shown one more. The
// directory's screen_NNNN.png files from an earlier run are removed first, so that the set is this
// run's. A picture that cannot be written (a full disk) ends the recording, not the run: the error
// is kept for the run's report (error()).
class ScreenRecorder {
 public:
  explicit ScreenRecorder(std::string dir) : dir_(std::move(dir)), error_(std::make_shared<std::string>()) {
    namespace fs = std::filesystem;
    fs::create_directories(dir_);
    for (const fs::directory_entry& e : fs::directory_iterator(dir_))
      if (is_screen_picture_name(e.path().filename().string()) && e.is_regular_file()) fs::remove(e.path());
  }
  void operator()(const sim::VideoCapture& screen) {
    if (!error_->empty() || screen.last_frame() == last_) return;
    last_ = screen.last_frame();
    char name[32];
    std::snprintf(name, sizeof name, "screen_%04u.png", written_++);
    try {
      write_png((std::filesystem::path(dir_) / name).string(), image_of_screen(screen));
    } catch (const std::exception& e) {
      *error_ = std::string(e.what()) + " (--screen-frames: no more pictures written)";
    }
  }
  // Shared by the copies the simulation holds: empty while every picture was written.
  std::shared_ptr<const std::string> error() const { return error_; }

 private:
  // screen_ and four or more digits, then .png: the names operator() writes.
  static bool is_screen_picture_name(const std::string& n) {
    constexpr std::string_view kPrefix = "screen_", kSuffix = ".png";
    if (n.size() < kPrefix.size() + 4 + kSuffix.size()) return false;
    if (n.compare(0, kPrefix.size(), kPrefix) != 0) return false;
    if (n.compare(n.size() - kSuffix.size(), kSuffix.size(), kSuffix) != 0) return false;
    const std::string digits = n.substr(kPrefix.size(), n.size() - kPrefix.size() - kSuffix.size());
    return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  }
  std::string dir_;
  std::vector<uint32_t> last_;
  unsigned written_ = 0;
  std::shared_ptr<std::string> error_;
};

// Whether the last byte written to stdout (by SIM_PUTCHAR or a stdio UART) left a line open, so
// that the summary's JSON can start a line of its own.
struct StdoutTail {
  bool line_open = false;
  void wrote(const char* data, size_t n) {
    if (n > 0) line_open = data[n - 1] != '\n';
  }
  void end_line() {
    if (line_open) std::cout << '\n';
    line_open = false;
  }
};

// SIM_PUTCHAR's stream: std::cout, watched by a StdoutTail.
class TrackedStdout final : public std::streambuf {
 public:
  explicit TrackedStdout(StdoutTail& tail) : tail_(tail) {}

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    const char ch = static_cast<char>(c);
    tail_.wrote(&ch, 1);
    return std::cout.rdbuf()->sputc(ch);
  }
  std::streamsize xsputn(const char* data, std::streamsize n) override {
    tail_.wrote(data, static_cast<size_t>(n));
    return std::cout.rdbuf()->sputn(data, n);
  }
  int sync() override { return std::cout.rdbuf()->pubsync(); }

 private:
  StdoutTail& tail_;
};

// The stdio UART, watched by a StdoutTail.
class TrackedSerial final : public sim::SerialEndpoint {
 public:
  TrackedSerial(std::unique_ptr<sim::SerialEndpoint> inner, StdoutTail& tail) : inner_(std::move(inner)), tail_(tail) {}
  size_t read(uint8_t* buf, size_t max) override { return inner_->read(buf, max); }
  void write(const uint8_t* data, size_t len) override {
    tail_.wrote(reinterpret_cast<const char*>(data), len);
    inner_->write(data, len);
  }
  void flush() override { inner_->flush(); }
  bool paced() const override { return inner_->paced(); }
  bool ended() const override { return inner_->ended(); }

 private:
  std::unique_ptr<sim::SerialEndpoint> inner_;
  StdoutTail& tail_;
};

// SIGINT and SIGTERM end the run as the cycle limit would (the summary printed, the trace closed,
// the outputs written), with the status a shell gives a process the signal killed (128 + signal).
std::atomic<bool> g_stop_requested{false};
volatile std::sig_atomic_t g_stop_signal = 0;

void request_stop(int sig) {
  g_stop_signal = sig;
  g_stop_requested.store(true, std::memory_order_relaxed);
}

class StopOnSignals {
 public:
  StopOnSignals() {
    old_int_ = std::signal(SIGINT, request_stop);
    old_term_ = std::signal(SIGTERM, request_stop);
  }
  ~StopOnSignals() {
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  void (*old_int_)(int);
  void (*old_term_)(int);
};

// The command's status: the firmware's exit code when it exited with one a process can have.
// Codes outside 0..255 (a tohost word can carry 31 bits) would be cut to their low byte, and 256
// would read as success, so they give 1; the code itself is in the summary and the JSON.
int status_of(const sim::SimResult& r) {
  switch (r.reason) {
    case sim::StopReason::CycleLimit: return kCycleLimitStatus;
    case sim::StopReason::InputEnded: return 0;
    case sim::StopReason::Stopped: return 128 + (g_stop_signal ? static_cast<int>(g_stop_signal) : SIGINT);
    case sim::StopReason::Stuck: return 1;
    case sim::StopReason::Exit:
    case sim::StopReason::ToHost: break;
  }
  return r.exit_code >= 0 && r.exit_code <= 255 ? r.exit_code : 1;
}

// --trace: FST's writer deletes whatever is at its path and creates a new file there, so only a
// regular file (or nothing) may be there: not a device, and not a link, which would be replaced
// rather than written through.
void require_trace_path(const std::string& path) {
  if (path.empty()) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(path, ec);
  if (ec || !fs::exists(st)) return;
  if (fs::is_symlink(st))
    throw std::runtime_error(path + ": is a symbolic link; the trace writer would replace it (name its target)");
  if (!fs::is_regular_file(st))
    throw std::runtime_error(path + ": is not a regular file; the trace writer deletes what is there first");
}

int run_sim(const SimArgs& a) {
  const auto [frame_w, frame_h] = parse_frame_size(a.frame_size);
  if (uint64_t{frame_w} * frame_h > sim::SocSim::kFbPixels)
    throw std::runtime_error("--frame-size " + a.frame_size + " exceeds the framebuffer of " +
                             std::to_string(sim::SocSim::kFbPixels) + " pixels");
  const sim::ElfImage elf = sim::load_elf(a.elf);
  // What can only fail after the run is checked before it, so a long run is not lost to a typo;
  // and what the harness refuses is refused before anything is opened or created.
  try {
    sim::check_runnable(elf);
  } catch (const std::exception& e) {
    throw std::runtime_error(a.elf + ": " + e.what());
  }
  const SignatureRange signature = a.signature.empty() ? SignatureRange{} : signature_range(elf, a.elf);
  require_output_files({&a.signature, &a.screen, &a.frame, &a.trace});
  for (const std::string* out : {&a.signature, &a.screen, &a.frame, &a.trace}) {
    if (!out->empty() && same_output_file(*out, a.elf))
      throw std::runtime_error(*out + ": is the ELF being run; an output would overwrite it");
    if (!out->empty() && !a.screen_frames.empty() && same_output_file(*out, a.screen_frames))
      throw std::runtime_error(*out + ": is also --screen-frames' directory");
  }
  if (!a.screen_frames.empty() && std::filesystem::exists(a.screen_frames) &&
      !std::filesystem::is_directory(a.screen_frames))
    throw std::runtime_error(a.screen_frames + ": --screen-frames needs a directory, and this is a file");
  require_trace_path(a.trace);

  sim::SimOptions opt;
  opt.max_cycles = a.max_cycles;
  opt.stall_seed = a.stall_seed;
  opt.trace_path = a.trace;
  opt.gpu_clock_gate = !a.no_gpu_gate;
  opt.capture_screen = !a.screen.empty() || !a.screen_frames.empty();
  opt.profile_pcs = a.hotspots;
  opt.stop = &g_stop_requested;
  std::shared_ptr<const std::string> screen_frames_error;
  if (!a.screen_frames.empty()) {
    ScreenRecorder recorder(a.screen_frames);
    screen_frames_error = recorder.error();
    opt.on_screen_frame = std::move(recorder);
  }

  StdoutTail tail;
  TrackedStdout putchar_buf(tail);
  std::ostream putchar_out(&putchar_buf);
  std::unique_ptr<sim::SerialEndpoint> uart;
  if (a.uart == "pty") {
    std::string path;
    uart = sim::open_pty_serial(path);
    // On stdout, on a line of its own, before the run starts: where scripts and people look for it.
    std::cout << "htx sim: UART on " << path << std::endl;
  } else {
    uart = std::make_unique<TrackedSerial>(sim::open_stdio_serial(), tail);
  }

  sim::SocSim soc(elf, opt, uart.get(), putchar_out);
  sim::SimResult r;
  {
    StopOnSignals stop_on_signals;
    r = soc.run();
  }
  uart.reset();  // flushes the UART's last bytes before the summary

  // Every output is written even if another fails; the run's result is reported either way.
  std::vector<std::string> output_errors;
  auto write_output = [&output_errors](const std::string& path, const auto& write) {
    if (path.empty()) return;
    try {
      write();
    } catch (const std::exception& e) {
      output_errors.push_back(e.what());
    }
  };
  if (screen_frames_error && !screen_frames_error->empty()) output_errors.push_back(*screen_frames_error);
  write_output(a.signature, [&] { write_signature(soc, signature, a.signature); });
  write_output(a.screen, [&] { write_screen(*soc.screen(), a.screen); });
  const std::vector<uint16_t> frame = soc.read_frame(frame_w, frame_h);
  write_output(a.frame, [&] {
    write_png(a.frame, image_from_rgb565(static_cast<int>(frame_w), static_cast<int>(frame_h), frame));
  });
  char crc_hex[16];
  std::snprintf(crc_hex, sizeof crc_hex, "%08x", sim::frame_crc32(frame));

  const double cpi = r.instret ? static_cast<double>(r.cycles) / static_cast<double>(r.instret) : 0.0;
  const double rate = r.seconds > 0 ? static_cast<double>(r.cycles) / r.seconds : 0.0;
  int status = status_of(r);
  if (r.reason == sim::StopReason::CycleLimit) {
    std::cerr << "htx sim: cycle limit of " << a.max_cycles
              << " cycles reached before the firmware exited (raise --max-cycles?); status "
              << kCycleLimitStatus << "\n";
  } else if (r.reason == sim::StopReason::InputEnded) {
    tail.end_line();  // ends the line of the prompt the firmware was waiting at
    std::cerr << "htx sim: standard input ended and the firmware waits for more input: stopped, status 0\n";
  } else if (r.reason == sim::StopReason::Stopped) {
    std::cerr << "htx sim: stopped by signal " << (status - 128) << "; status " << status << "\n";
  }
  if (!r.note.empty()) std::cerr << "htx sim: " << r.note << "\n";
  // The firmware's exit code only when it exited (a cycle limit or ended input has none).
  const bool exited = r.reason == sim::StopReason::Exit || r.reason == sim::StopReason::ToHost;
  char exit_code[64] = "";
  if (exited && r.exit_code == status) std::snprintf(exit_code, sizeof exit_code, ", exit code %d", r.exit_code);
  if (exited && r.exit_code != status)
    std::snprintf(exit_code, sizeof exit_code, ", exit code %d (not a process status: status %d)", r.exit_code, status);
  char summary[256];
  std::snprintf(summary, sizeof summary, "htx sim: %s%s: %llu cycles, %llu instructions, CPI %.3f (%.2f Mcycles/s)\n",
                sim::to_string(r.reason), exit_code, static_cast<unsigned long long>(r.cycles),
                static_cast<unsigned long long>(r.instret), cpi, rate / 1e6);
  std::cerr << summary;
  for (const std::string& e : output_errors) std::cerr << "htx sim: " << e << "\n";
  // A failed output is the command's failure (the firmware's own status is in the summary).
  if (!output_errors.empty()) status = 1;
  if (a.profile) print_profile(r.profile);
  std::vector<sim::FunctionCost> hotspots;
  if (r.pcs) {
    hotspots = sim::cost_by_function(*r.pcs, elf.functions);
    print_hotspots(hotspots, r.cycles);
  }
  if (a.json) {
    nlohmann::json j = {{"exit_code", status},       {"reason", sim::to_string(r.reason)},
                        {"cycles", r.cycles},        {"instret", r.instret},
                        {"cpi", cpi},                {"seconds", r.seconds},
                        {"cycles_per_second", rate}, {"frame_crc32", crc_hex}};
    if (exited) j["firmware_code"] = r.exit_code;
    if (!output_errors.empty()) j["errors"] = output_errors;
    if (a.profile) {
      nlohmann::json p = nlohmann::json::object();
      for (size_t i = 0; i < sim::CpuProfile::kCauses; ++i) p[sim::CpuProfile::kNames[i]] = r.profile.counts[i];
      j["profile"] = p;
    }
    if (r.pcs) {
      nlohmann::json list = nlohmann::json::array();
      for (const sim::FunctionCost& c : hotspots) {
        nlohmann::json callers = nlohmann::json::array();
        for (const sim::FunctionCaller& k : c.callers) callers.push_back({{"function", k.name}, {"calls", k.calls}});
        list.push_back({{"function", c.name},
                        {"addr", c.addr},
                        {"cycles", c.cycles},
                        {"instructions", c.instructions},
                        {"calls", c.calls},
                        {"inclusive", c.inclusive},
                        {"callers", callers}});
      }
      j["hotspots"] = list;
    }
    tail.end_line();  // the object is a line of its own, after whatever the firmware printed
    std::cout << j.dump() << std::endl;
  }
  return status;
}
#else
int run_sim(const SimArgs&) {
  throw std::runtime_error("this htx was built without the Verilated SoC (HTX_BUILD_RTL=OFF)");
}
#endif

}  // namespace

void register_sim(CLI::App& app) {
  auto args = std::make_shared<SimArgs>();
  CLI::App* cmd = app.add_subcommand("sim", "Run a firmware ELF on the simulated SoC (Verilator)");
  cmd->add_option("--elf", args->elf, "Firmware ELF (rv32im) to load into RAM")->required()->check(CLI::ExistingFile);
  cmd->add_option("--uart", args->uart, "Where the UART goes: stdio, or pty (prints the terminal's path)")
      ->check(CLI::IsMember({"stdio", "pty"}));
  cmd->add_option("--max-cycles", args->max_cycles, "Stop after this many clocks (status 124)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 62));
  cmd->add_option("--signature", args->signature,
                  "Write the words from begin_signature to end_signature, 8 hex digits a line");
  cmd->add_option("--trace", args->trace, "Write an FST waveform to this file");
  cmd->add_option("--stall-seed", args->stall_seed, "Insert random wait states on every bus slave, seeded");
  cmd->add_flag("--no-gpu-gate", args->no_gpu_gate,
                "Clock the GPU on every cycle, even while it is idle (same results, several times slower)");
  cmd->add_option("--frame", args->frame,
                  "At exit, write the colour page the raster unit draws into (the frame drawn last; --frame-size pixels) as a PNG");
  cmd->add_option("--screen", args->screen,
                  "At exit, write the last whole frame the video scan-out showed (640x480, what a board's "
                  "screen shows; black while the firmware has not turned the video on) as a PNG");
  cmd->add_option("--screen-frames", args->screen_frames,
                  "Write every picture the video scan-out showed, once each (a frame equal to the one "
                  "before it is skipped), as DIR/screen_NNNN.png; DIR's screen_NNNN.png from an earlier run "
                  "are removed first");
  cmd->add_option("--frame-size", args->frame_size,
                  "Size of the frame in the colour window, WIDTHxHEIGHT with stride WIDTH (default 160x120)");
  cmd->add_flag("--profile", args->profile,
                "Print where the CPU's clocks went: execute, data bus, mul/div, CSR order, load use, late "
                "result, redirect, predicted jump, fetch (with --json, also as \"profile\")");
  cmd->add_flag("--hotspots", args->hotspots,
                "Print the functions that took the most clocks (the ELF's symbols), with their clocks from call "
                "to return, calls, instructions and CPI: each clock is charged to the instruction in execute, a "
                "bubble's to the one before it (with --json, every function and its callers as \"hotspots\")");
  cmd->add_flag("--json", args->json,
                "Print one JSON object (exit_code, cycles, instret, cpi, ..., frame_crc32) as the last line of stdout");
  cmd->callback([args]() {
    int status = 1;
    try {
      status = run_sim(*args);
    } catch (const std::exception& e) {
      std::cerr << "htx sim: " << e.what() << "\n";
      status = 1;
    }
    std::exit(status_after_output("htx sim", status));  // the firmware's exit code
  });
}

}  // namespace htx
