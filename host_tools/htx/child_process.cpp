#include "child_process.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace htx {

std::string ChildStatus::describe() const {
  if (spawn_error != 0) return std::string("could not start: ") + std::strerror(spawn_error);
  return exited ? "exit status " + std::to_string(exit_status) : std::string("killed by a signal");
}

ChildStatus run_child(const std::vector<std::string>& argv, const std::string& cwd) {
  if (argv.empty()) throw std::invalid_argument("run_child: no program");
  std::vector<char*> cargv;
  for (const std::string& s : argv) cargv.push_back(const_cast<char*>(s.c_str()));
  cargv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!cwd.empty() && posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str()) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    throw std::runtime_error("cannot run " + argv[0] + " in '" + cwd + "'");
  }
  pid_t pid = 0;
  ChildStatus status;
  status.spawn_error = posix_spawnp(&pid, cargv[0], &actions, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (status.spawn_error != 0) return status;

  int wstatus = 0;
  while (waitpid(pid, &wstatus, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("waiting for ") + argv[0] + ": " + std::strerror(errno));
  }
  status.exited = WIFEXITED(wstatus);
  status.exit_status = status.exited ? WEXITSTATUS(wstatus) : 0;
  return status;
}

}  // namespace htx
