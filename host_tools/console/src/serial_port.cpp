#include "htx/console/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <stdexcept>

namespace htx::console {

namespace {

speed_t speed_of(unsigned baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    case 1000000: return B1000000;
    case 1500000: return B1500000;
    case 2000000: return B2000000;
    case 3000000: return B3000000;
    default:
      throw std::invalid_argument("baud " + std::to_string(baud) +
                                  ": want 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600, 1000000, "
                                  "1500000, 2000000 or 3000000");
  }
}

}  // namespace

void SerialPort::check_baud(unsigned baud) { speed_of(baud); }

SerialPort::SerialPort(const std::string& path, unsigned baud) : path_(path) {
  const speed_t speed = speed_of(baud);
  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error("cannot open '" + path + "': " + std::strerror(errno));
  // One client at a time: a second one's bytes would be taken as the first one's answers (a grab
  // "damaged", an upload waiting past its timeout). An advisory lock, which every htx tool takes;
  // not TIOCEXCL, which would outlive the client on a pty whose other side stays open.
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    if (err == EWOULDBLOCK)
      throw std::runtime_error("'" + path + "' is in use by another htx client (one at a time)");
    throw std::runtime_error("cannot lock '" + path + "': " + std::strerror(err));
  }
  termios t{};
  if (::tcgetattr(fd_, &t) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw std::runtime_error("'" + path + "' is not a serial port or terminal: " + why);
  }
  ::cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS | PARENB);
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  ::cfsetispeed(&t, speed);
  ::cfsetospeed(&t, speed);
  if (::tcsetattr(fd_, TCSANOW, &t) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw std::runtime_error("cannot configure '" + path + "': " + why);
  }
}

void SerialPort::set_baud(unsigned baud) {
  const speed_t speed = speed_of(baud);
  termios t{};
  if (::tcgetattr(fd_, &t) != 0) throw std::runtime_error("reading '" + path_ + "''s settings: " + std::strerror(errno));
  ::cfsetispeed(&t, speed);
  ::cfsetospeed(&t, speed);
  if (::tcsetattr(fd_, TCSADRAIN, &t) != 0)
    throw std::runtime_error("cannot set '" + path_ + "' to " + std::to_string(baud) + " baud: " + std::strerror(errno));
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

void SerialPort::write(const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error("writing to '" + path_ + "': " + std::strerror(errno));
    done += static_cast<size_t>(n);
  }
}

size_t SerialPort::read_some(uint8_t* buf, size_t size, std::chrono::milliseconds timeout) {
  pollfd p{fd_, POLLIN, 0};
  // (poll takes an int of milliseconds: a longer wait is cut to about 24 days, never wrapped.)
  const int r = ::poll(&p, 1, static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(timeout.count(), 0, INT_MAX)));
  if (r < 0 && errno == EINTR) return 0;
  if (r < 0) throw std::runtime_error("waiting on '" + path_ + "': " + std::strerror(errno));
  if (r == 0) return 0;
  const ssize_t n = ::read(fd_, buf, size);
  // A pseudo-terminal whose other side closed reads EIO (or 0): the simulation has ended.
  if (n == 0 || (n < 0 && errno == EIO) || (p.revents & (POLLHUP | POLLERR) && n <= 0))
    throw std::runtime_error("'" + path_ + "' was closed at the other end (the board or simulation went away)");
  if (n < 0) throw std::runtime_error("reading '" + path_ + "': " + std::strerror(errno));
  return static_cast<size_t>(n);
}

}  // namespace htx::console
