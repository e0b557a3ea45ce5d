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

bool SocConsole::take_result(std::chrono::milliseconds wait) {
  if (ended_ || failure_) return true;
  if (result_.wait_for(wait) != std::future_status::ready) return false;
  thread_.join();
  try {
    ended_ = result_.get();
  } catch (...) {
    failure_ = std::current_exception();
  }
  return true;
}

sim::SimResult SocConsole::finish(std::chrono::milliseconds limit) {
  if (!take_result(limit)) {
    stop_ = true;
    thread_.join();
    throw std::runtime_error("the simulated SoC did not end after quit");
  }
  if (failure_) std::rethrow_exception(failure_);  // what the run threw
  return *ended_;
}

std::optional<std::string> SocConsole::ended_early() {
  if (!take_result(std::chrono::milliseconds(0))) return std::nullopt;
  if (failure_) {
    try {
      std::rethrow_exception(failure_);
    } catch (const std::exception& e) {
      return std::string("the simulated SoC had failed: ") + e.what();
    } catch (...) {
      return std::string("the simulated SoC had failed");
    }
  }
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
