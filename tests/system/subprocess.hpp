// Runs a program for a system test: argv, captured stdout/stderr, a hard time limit (the child is
// killed when it passes), and incremental reading for interactive tests.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace htx::test {

struct RunResult {
  int status = -1;  // exit status, or -1 if killed/signalled
  bool timed_out = false;
  std::string out;
  std::string err;
};

RunResult run_program(const std::vector<std::string>& argv, std::chrono::milliseconds limit);

// A child whose stdout is read incrementally (stderr is inherited, so it shows in the test log).
class Child {
 public:
  // with_input: its standard input is a pipe written by write_input (otherwise /dev/null).
  explicit Child(const std::vector<std::string>& argv, bool with_input = false);
  // On a pseudo-terminal of its own (standard input, output and error), as a person's terminal
  // runs it: write_input types keys, read_until reads what it shows. `env`: NAME=VALUE entries set
  // in the child (TERM for a program that edits lines).
  struct Terminal {
    std::vector<std::string> env;
  };
  Child(const std::vector<std::string>& argv, const Terminal& terminal);
  ~Child();  // kills the child if it is still running
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  // Reads stdout until `needle` has appeared in everything read so far, or the limit passes.
  bool read_until(const std::string& needle, std::chrono::milliseconds limit);
  const std::string& output() const { return out_; }
  void write_input(const std::string& text);
  void close_input();  // the child reads the end of its input
  void send_signal(int sig);  // as kill(2), while it runs
  // Waits for the child to exit; -1 if it had to be killed at the limit.
  int wait(std::chrono::milliseconds limit);

 private:
  pid_t pid_ = -1;
  int out_fd_ = -1;
  int in_fd_ = -1;
  std::string out_;
};

// Reads from `fd` (non-blocking or not) until `needle` appears in `acc`, or the limit passes.
bool read_fd_until(int fd, std::string& acc, const std::string& needle, std::chrono::milliseconds limit);

// Opens a terminal (a pty `htx sim --uart pty` printed) in raw mode, as a serial program does;
// -1 when it cannot be opened or set raw.
int open_raw_terminal(const std::string& path);

}  // namespace htx::test
