// Where the simulated UART's bytes go on the host: a pseudo-terminal, stdio, or (in tests) memory.
// Reads never block: the simulation polls between clocks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace htx::sim {

class SerialEndpoint {
 public:
  virtual ~SerialEndpoint() = default;
  // Up to `max` received bytes into `buf`; 0 when none are waiting (never blocks).
  virtual size_t read(uint8_t* buf, size_t max) = 0;
  // Bytes the SoC sent. Never blocks; an endpoint may buffer what it cannot pass on yet.
  virtual void write(const uint8_t* data, size_t len) = 0;
  // Passes on buffered output (called at the end of a run and now and then while running).
  virtual void flush() {}
  // Input is a script, not a person or a serial program: the harness then sends it only as fast
  // as the UART's receive FIFO has room (as a terminal with flow control would), so none is lost.
  virtual bool paced() const { return false; }
  // No more input will ever come (a script's end of file); a terminal or a pty never ends.
  virtual bool ended() const { return false; }
};

// A pseudo-terminal in raw mode; any serial program can open path(). Output the program has not
// read yet is kept (the harness holds the slave side open), so nothing sent before it attaches is lost.
std::unique_ptr<SerialEndpoint> open_pty_serial(std::string& path_out);
// Standard input and output. Input is read only when available; EOF ends input (ended()). When
// stdin is not a terminal (a pipe or a file) it is paced().
std::unique_ptr<SerialEndpoint> open_stdio_serial();

}  // namespace htx::sim
