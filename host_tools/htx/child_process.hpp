// Running another program (gnuplot, a board's loader) without a shell: its arguments are passed as
// they are, so a path with a quote or a space in it is only a path.
#pragma once

#include <string>
#include <vector>

namespace htx {

struct ChildStatus {
  int spawn_error = 0;  // errno of a failed start (ENOENT: not on PATH); 0 when it ran
  bool exited = false;  // it ended by exiting (not by a signal)
  int exit_status = 0;  // its status when it exited

  bool succeeded() const { return spawn_error == 0 && exited && exit_status == 0; }
  // "exit status N", "killed by a signal", or the reason it could not start.
  std::string describe() const;
};

// Runs argv[0] (looked up on PATH) with argv, in the directory `cwd` (this process's when empty),
// and waits for it to end.
ChildStatus run_child(const std::vector<std::string>& argv, const std::string& cwd = "");

}  // namespace htx
