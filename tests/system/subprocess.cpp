#include "subprocess.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

namespace htx::test {
namespace {

using Clock = std::chrono::steady_clock;

// execv's argument vector (pointers into argv, which outlives the call).
std::vector<char*> exec_args(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  return args;
}

// in_fd < 0: standard input from /dev/null.
pid_t spawn(const std::vector<std::string>& argv, int out_fd, int err_fd, int in_fd = -1) {
  std::vector<char*> args = exec_args(argv);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int in = in_fd >= 0 ? in_fd : open("/dev/null", O_RDONLY);
    dup2(in, STDIN_FILENO);
    if (in != STDIN_FILENO) close(in);
    if (out_fd >= 0) dup2(out_fd, STDOUT_FILENO);
    if (err_fd >= 0) dup2(err_fd, STDERR_FILENO);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

int remaining_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() > 0 ? static_cast<int>(left.count()) : 0;
}

int decode_status(int st) { return WIFEXITED(st) ? WEXITSTATUS(st) : -1; }

int wait_with_limit(pid_t pid, Clock::time_point deadline, bool& timed_out) {
  int st = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &st, WNOHANG);
    if (r == pid) return decode_status(st);
    if (r < 0 && errno != EINTR) return -1;
    if (Clock::now() >= deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &st, 0);
      timed_out = true;
      return -1;
    }
    usleep(2000);
  }
}

}  // namespace

RunResult run_program(const std::vector<std::string>& argv, std::chrono::milliseconds limit) {
  int out_pipe[2], err_pipe[2];
  if (pipe(out_pipe) != 0 || pipe(err_pipe) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = spawn(argv, out_pipe[1], err_pipe[1]);
  close(out_pipe[1]);
  close(err_pipe[1]);
  RunResult res;
  const auto deadline = Clock::now() + limit;
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&res.out, &res.err};
  int open_fds = 2;
  while (open_fds > 0 && Clock::now() < deadline) {
    if (poll(fds, 2, remaining_ms(deadline)) <= 0) continue;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP))) continue;
      char buf[4096];
      const ssize_t n = read(fds[i].fd, buf, sizeof buf);
      if (n > 0) {
        sinks[i]->append(buf, static_cast<size_t>(n));
      } else {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  for (auto& f : fds) {
    if (f.fd >= 0) close(f.fd);
  }
  res.status = wait_with_limit(pid, deadline, res.timed_out);
  return res;
}

bool read_fd_until(int fd, std::string& acc, const std::string& needle, std::chrono::milliseconds limit) {
  const auto deadline = Clock::now() + limit;
  while (acc.find(needle) == std::string::npos) {
    pollfd p{fd, POLLIN, 0};
    const int left = remaining_ms(deadline);
    if (left == 0) return false;
    if (poll(&p, 1, left) <= 0) continue;
    char buf[1024];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n > 0) {
      acc.append(buf, static_cast<size_t>(n));
    } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
      return acc.find(needle) != std::string::npos;  // end of stream
    }
  }
  return true;
}

Child::Child(const std::vector<std::string>& argv, bool with_input) {
  int p[2];
  if (pipe(p) != 0) throw std::runtime_error("pipe failed");
  int in[2] = {-1, -1};
  if (with_input) {
    if (pipe2(in, O_CLOEXEC) != 0) {  // the child keeps only its end, as its standard input
      close(p[0]);
      close(p[1]);
      throw std::runtime_error("pipe failed");
    }
    // A write to a child that has ended fails with EPIPE (reported) instead of ending the test.
    signal(SIGPIPE, SIG_IGN);
  }
  pid_ = spawn(argv, p[1], -1, in[0]);
  close(p[1]);
  out_fd_ = p[0];
  if (with_input) {
    close(in[0]);
    in_fd_ = in[1];
  }
}

void Child::write_input(const std::string& text) {
  if (in_fd_ < 0) throw std::logic_error("Child: started without an input pipe");
  if (write(in_fd_, text.data(), text.size()) != static_cast<ssize_t>(text.size()))
    throw std::runtime_error("Child: writing its input failed");
}

void Child::close_input() {
  if (in_fd_ >= 0) close(in_fd_);
  in_fd_ = -1;
}

Child::~Child() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    int st;
    waitpid(pid_, &st, 0);
  }
  if (out_fd_ >= 0) close(out_fd_);
  close_input();
}

bool Child::read_until(const std::string& needle, std::chrono::milliseconds limit) {
  return read_fd_until(out_fd_, out_, needle, limit);
}

void Child::send_signal(int sig) {
  if (pid_ > 0) ::kill(pid_, sig);
}

int Child::wait(std::chrono::milliseconds limit) {
  bool timed_out = false;
  const int st = wait_with_limit(pid_, Clock::now() + limit, timed_out);
  pid_ = -1;
  return st;
}

Child::Child(const std::vector<std::string>& argv, const Terminal& terminal) {
  std::vector<char*> args = exec_args(argv);
  int master = -1;
  pid_ = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid_ < 0) throw std::runtime_error("forkpty failed");
  if (pid_ == 0) {
    for (const std::string& e : terminal.env) putenv(const_cast<char*>(e.c_str()));
    execv(args[0], args.data());
    _exit(127);
  }
  out_fd_ = master;
  in_fd_ = dup(master);  // (each closed once)
}

int open_raw_terminal(const std::string& path) {
  const int fd = open(path.c_str(), O_RDWR | O_NOCTTY);
  if (fd < 0) return -1;
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) {
    close(fd);
    return -1;
  }
  cfmakeraw(&tio);
  if (tcsetattr(fd, TCSANOW, &tio) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

}  // namespace htx::test
