// Console firmware (docs/console.md): uploads the render firmware's texture, greets, then reads
// command lines from the UART and carries them out (commands.hpp) until `quit` or the end of input.
#include <stdio.h>

#include "commands.hpp"
#include "htx/hal/video.h"
#include "line_reader.hpp"
#include "scene_store.hpp"
#include "soc_texture.hpp"

namespace {
constexpr uint32_t kMaxPolls = 20'000'000;
constexpr const char* kPrompt = "htx> ";
static_assert(console_app::kStoreBytes >= 4 * render_app::kTextureTexels, "the staging buffer is the texture's scratch at boot");
}  // namespace

int main() {
  const htx::render::UploadStatus up = render_app::upload_scene_texture(
      kMaxPolls, reinterpret_cast<uint32_t*>(console_app::staging_bytes()));
  if (up != htx::render::kUploadOk) {
    printf("console: texture upload failed with status %d\r\n", up);
    return 1;
  }
  htx::hal::video_enable(true);  // a board's screen shows the framebuffer from the start
  fputs("hypertex console. Type help.\r\n", stdout);
  char line[console_app::kMaxLine + 1];
  for (;;) {
    fputs(kPrompt, stdout);
    const console_app::LineStatus st = console_app::read_line(line);
    if (st == console_app::LineStatus::kEndOfInput) break;
    if (st == console_app::LineStatus::kOverrun) {
      fputs("error: input arrived faster than the console reads it and was lost; the line was dropped "
            "(send a line at a time)\r\n",
            stdout);
      continue;
    }
    if (st == console_app::LineStatus::kGarbled) {
      fputs("error: a byte of this line arrived garbled (no stop bit: is the terminal at the console's baud "
            "rate?) and was lost; the line was dropped\r\n",
            stdout);
      continue;
    }
    if (st == console_app::LineStatus::kTooLong) {
      printf("error: line longer than %u characters\r\n", static_cast<unsigned>(console_app::kMaxLine));
      continue;
    }
    if (console_app::run_command(line) == console_app::CommandResult::kQuit) break;
  }
  fputs("bye\r\n", stdout);
  return 0;
}
