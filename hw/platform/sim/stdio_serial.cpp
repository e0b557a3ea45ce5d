// Standard input/output endpoint. Input is polled with poll(2) and a zero timeout, so the
// simulation never waits for it; stdin's own blocking mode is left alone.
#include <poll.h>
#include <unistd.h>

#include <cstdio>

#include "htx/sim/serial_endpoint.hpp"

namespace htx::sim {
namespace {

class StdioSerial final : public SerialEndpoint {
 public:
  size_t read(uint8_t* buf, size_t max) override {
    if (eof_) return 0;
    pollfd p{STDIN_FILENO, POLLIN, 0};
    if (::poll(&p, 1, 0) <= 0 || !(p.revents & (POLLIN | POLLHUP))) return 0;
    const ssize_t n = ::read(STDIN_FILENO, buf, max);
    if (n <= 0) {
      eof_ = true;  // end of input (or an error): the UART simply receives nothing more
      return 0;
    }
    return static_cast<size_t>(n);
  }

  void write(const uint8_t* data, size_t len) override {
    std::fwrite(data, 1, len, stdout);
    for (size_t i = 0; i < len; ++i) {
      if (data[i] == '\n') {
        std::fflush(stdout);
        break;
      }
    }
  }

  void flush() override { std::fflush(stdout); }

  bool paced() const override { return script_; }
  bool ended() const override { return eof_; }

 private:
  bool eof_ = false;
  const bool script_ = !::isatty(STDIN_FILENO);  // a pipe or a file
};

}  // namespace

std::unique_ptr<SerialEndpoint> open_stdio_serial() { return std::make_unique<StdioSerial>(); }

}  // namespace htx::sim
