#if __has_include("htx/sim/soc_sim.hpp")
#include "soc_console.hpp"

#include <stdexcept>

#include "htx/sim/elf_image.hpp"

namespace htx {

namespace {

// Far beyond any exchange htx has with the console (a render and a grab of a scene of 16 KiB is
// some 40 M clocks); finish() and the destructor end it sooner.
constexpr uint64_t kMaxCycles = 20'000'000'000ull;

}  // namespace

SocConsole::SocConsole(const std::string& elf_path) {
  const sim::ElfImage elf = sim::load_elf(elf_path);
  uart_ = sim::open_pty_serial(pty_);
  sim::SimOptions opt;
  opt.max_cycles = kMaxCycles;
  opt.stop = &stop_;
  soc_ = std::make_unique<sim::SocSim>(elf, opt, uart_.get(), putchar_);
  result_ = done_.get_future();
  thread_ = std::thread([this] {
    try {
      done_.set_value(soc_->run());
    } catch (...) {
      done_.set_exception(std::current_exception());
    }
    // The pseudo-terminal closes once the run has ended (and how is known), so that a client
    // waiting on it fails at once rather than after its timeout.
    uart_.reset();
  });
}

SocConsole::~SocConsole() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

sim::SimResult SocConsole::finish(std::chrono::milliseconds limit) {
  if (failure_) throw std::runtime_error(*failure_);
  if (ended_) return *ended_;
  if (result_.wait_for(limit) != std::future_status::ready) {
    stop_ = true;
    thread_.join();
    throw std::runtime_error("the simulated SoC did not end after quit");
  }
  thread_.join();
  return result_.get();  // rethrows what the run threw
}

std::optional<std::string> SocConsole::ended_early() {
  if (!ended_ && !failure_) {
    if (result_.wait_for(std::chrono::milliseconds(0)) != std::future_status::ready) return std::nullopt;
    thread_.join();
    try {
      ended_ = result_.get();
    } catch (const std::exception& e) {
      failure_ = e.what();
    }
  }
  if (failure_) return "the simulated SoC had failed: " + *failure_;
  const sim::SimResult& r = *ended_;
  std::string how = "the simulated SoC had stopped after " + std::to_string(r.cycles) + " clocks: " +
                    sim::to_string(r.reason);
  if (r.reason == sim::StopReason::Exit || r.reason == sim::StopReason::ToHost)
    how += " with code " + std::to_string(r.exit_code);
  if (!r.note.empty()) how += " (" + r.note + ")";
  return how;
}

}  // namespace htx
#endif
