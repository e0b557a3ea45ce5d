// The lines a person types at `htx console`: edited, with the session's history (arrow keys,
// libedit's readline, when standard input is a terminal and the build has libedit), or read plain
// (a pipe, a script, or no libedit); and, while the console works, whether a whole line was typed
// since, without waiting. Both read the descriptor itself, so no line is left in a buffer that the
// other does not see.
#pragma once

#include <string>

namespace htx {

class LineInput {
 public:
  LineInput();
  LineInput(const LineInput&) = delete;
  LineInput& operator=(const LineInput&) = delete;

  // The next line (without its end), after `prompt` on standard output; a line typed while the
  // console worked comes first, printed after the prompt (an empty one is passed over: it only
  // stopped a spin). False at the end of the input.
  bool read(const std::string& prompt, std::string* line);
  // A whole line typed since, if there is one (true; it is then read's next, not given here).
  // Never waits. The end of the input is not a line.
  bool line_typed();

 private:
  bool take_line(std::string* line);  // the first whole line of pending_, if there is one
  bool fill(int timeout_ms);          // reads what standard input has; false at its end

  bool editing_ = false;
  bool ended_ = false;
  std::string pending_;  // read from the descriptor, not yet given out
};

}  // namespace htx
