#include "line_input.hpp"

#include <poll.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>

#ifdef HTX_HAVE_LIBEDIT
#include <editline/readline.h>
#endif

namespace htx {

LineInput::LineInput() {
#ifdef HTX_HAVE_LIBEDIT
  editing_ = isatty(STDIN_FILENO) && isatty(STDOUT_FILENO);
  if (editing_) rl_readline_name = "htx";  // (its settings in ~/.editrc: `htx:bind ...`)
#endif
}

bool LineInput::take_line(std::string* line) {
  const size_t nl = pending_.find('\n');
  if (nl == std::string::npos) return false;
  *line = pending_.substr(0, nl);
  if (!line->empty() && line->back() == '\r') line->pop_back();
  pending_.erase(0, nl + 1);
  return true;
}

bool LineInput::fill(int timeout_ms) {
  if (ended_) return false;
  pollfd in{STDIN_FILENO, POLLIN, 0};
  if (poll(&in, 1, timeout_ms) <= 0) return true;
  char buf[4096];
  const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
  if (n <= 0) {
    ended_ = true;
    return false;
  }
  pending_.append(buf, static_cast<size_t>(n));
  return true;
}

bool LineInput::line_typed() {
  fill(0);
  return pending_.find('\n') != std::string::npos;
}

bool LineInput::read(const std::string& prompt, std::string* line) {
  // Lines typed while the console worked, shown after the prompt; an empty one only stopped it.
  while (take_line(line))
    if (!line->empty()) {
      std::cout << prompt << *line << "\n" << std::flush;
      return true;
    }
#ifdef HTX_HAVE_LIBEDIT
  // (A line begun while the console worked, not yet ended, is finished plain.)
  if (editing_ && pending_.empty()) {
    std::cout << std::flush;
    char* edited = readline(prompt.c_str());
    if (!edited) {
      ended_ = true;
      return false;
    }
    *line = edited;
    std::free(edited);
    if (!line->empty()) add_history(line->c_str());
    return true;
  }
#endif
  std::cout << prompt << std::flush;
  // A terminal echoes what is typed; a script's lines (a pipe, a file) are shown after the
  // prompt, so that a log reads as a session.
  const bool show = !isatty(STDIN_FILENO);
  while (!take_line(line))
    if (!fill(-1)) {
      if (pending_.empty()) {
        if (show) std::cout << "\n" << std::flush;  // ends the last prompt's line
        return false;
      }
      *line = pending_;  // a last line without its end
      pending_.clear();
      break;
    }
  if (show) std::cout << *line << "\n" << std::flush;
  return true;
}

}  // namespace htx
