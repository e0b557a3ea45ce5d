// Pseudo-terminal endpoint: posix_openpt/grantpt/unlockpt/ptsname, raw mode, non-blocking master.
#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "htx/sim/serial_endpoint.hpp"

namespace htx::sim {
namespace {

[[noreturn]] void fail(const char* what) {
  throw std::runtime_error(std::string("pseudo-terminal: ") + what + ": " + std::strerror(errno));
}

class PtySerial final : public SerialEndpoint {
 public:
  explicit PtySerial(std::string& path_out) {
    master_ = posix_openpt(O_RDWR | O_NOCTTY);
    if (master_ < 0) fail("posix_openpt");
    if (grantpt(master_) != 0) fail("grantpt");
    if (unlockpt(master_) != 0) fail("unlockpt");
    const char* name = ptsname(master_);
    if (name == nullptr) fail("ptsname");
    path_out = name;
    // Holding the slave open keeps the master readable/writable when no program is attached and
    // keeps unread output for the program that attaches later.
    slave_ = ::open(name, O_RDWR | O_NOCTTY);
    if (slave_ < 0) fail("open slave");
    termios tio{};
    if (tcgetattr(slave_, &tio) != 0) fail("tcgetattr");
    cfmakeraw(&tio);
    if (tcsetattr(slave_, TCSANOW, &tio) != 0) fail("tcsetattr");
    const int flags = fcntl(master_, F_GETFL);
    if (flags < 0 || fcntl(master_, F_SETFL, flags | O_NONBLOCK) != 0) fail("fcntl O_NONBLOCK");
  }
  ~PtySerial() override {
    flush();
    // Closing the master hangs the terminal up, and what it has not read yet is lost (the echo
    // firmware's last byte, for one). Give an attached program up to a second to read it: the
    // slave's input queue, which our own slave descriptor can measure, empties as it reads. The
    // kernel moves written bytes into that queue a little later, so it must stay empty for 50 ms.
    int empty_ms = 0;
    for (int waited_ms = 0; waited_ms < 1000 && empty_ms < 50; waited_ms += 5) {
      flush();
      int unread = 0;
      const bool empty = pending_.empty() && (::ioctl(slave_, FIONREAD, &unread) != 0 || unread == 0);
      empty_ms = empty ? empty_ms + 5 : 0;
      ::usleep(5000);
    }
    if (slave_ >= 0) ::close(slave_);
    if (master_ >= 0) ::close(master_);
  }

  size_t read(uint8_t* buf, size_t max) override {
    const ssize_t n = ::read(master_, buf, max);
    return n > 0 ? static_cast<size_t>(n) : 0;  // EAGAIN: nothing typed yet
  }

  void write(const uint8_t* data, size_t len) override {
    pending_.insert(pending_.end(), data, data + len);
    flush();
  }

  void flush() override {
    while (!pending_.empty()) {
      const ssize_t n = ::write(master_, pending_.data(), pending_.size());
      if (n <= 0) break;  // the terminal's buffer is full: keep the rest for later
      pending_.erase(pending_.begin(), pending_.begin() + n);
    }
    // Bound the backlog if nobody ever reads: drop the oldest output past 1 MiB.
    constexpr size_t kMaxBacklog = 1u << 20;
    if (pending_.size() > kMaxBacklog) {
      pending_.erase(pending_.begin(), pending_.end() - static_cast<std::ptrdiff_t>(kMaxBacklog));
    }
  }

 private:
  int master_ = -1;
  int slave_ = -1;
  std::vector<uint8_t> pending_;
};

}  // namespace

std::unique_ptr<SerialEndpoint> open_pty_serial(std::string& path_out) {
  return std::make_unique<PtySerial>(path_out);
}

}  // namespace htx::sim
