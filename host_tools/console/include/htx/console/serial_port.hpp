// A serial line to a board or to `htx sim --uart pty`: opened raw (8N1, no echo, no flow control,
// no line editing) at a baud rate, with reads that give up after a timeout. The same code serves a
// USB serial adapter and a pseudo-terminal, which ignores the baud rate.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

namespace htx::console {

class SerialPort {
 public:
  // Throws std::runtime_error naming the path and the reason.
  SerialPort(const std::string& path, unsigned baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Another rate from now on (after what was written has gone). Throws on a rate it does not know.
  void set_baud(unsigned baud);
  // Throws std::invalid_argument, listing the rates it knows, if a port cannot be set to `baud`.
  static void check_baud(unsigned baud);
  void write(const std::string& bytes);
  // Waits up to `timeout` for at least one byte; returns how many were read (0: the time passed).
  // Throws when the other end has gone (the simulation ended) or on a read error.
  size_t read_some(uint8_t* buf, size_t size, std::chrono::milliseconds timeout);

 private:
  int fd_ = -1;
  std::string path_;
};

}  // namespace htx::console
