// The console's text commands (docs/console.md): parsing a line and carrying it out.
#pragma once

namespace console_app {

enum class CommandResult { kDone, kQuit };

// Carries out one command line; prints its output, or `error: ...` on a bad command or argument.
CommandResult run_command(char* line);

}  // namespace console_app
