#include "line_reader.hpp"

#include <stdio.h>

#include "htx/fw/console_packet.h"
#include "htx/hal/uart.h"

namespace console_app {

namespace {
constexpr int kCtrlC = 0x03;
constexpr int kBackspace = 0x08;
constexpr int kDelete = 0x7F;
bool g_after_cr = false;  // swallow the LF of a CR LF pair
// Inside a packet frame (after a zero byte, before the next): a packet the host sent again after
// an upload had ended (its copy of a packet the console had taken), never text, since text holds
// no zero byte. Bounded by a frame's length: a lone zero (a NUL typed, Ctrl-@) makes the console
// skip up to kPacketMaxLine (251) bytes after it, line ends included (htx refuses to send one).
size_t g_frame_bytes_left = 0;
int g_unread = EOF;       // a byte given back by unread_byte
}  // namespace

void unread_byte(int c) { g_unread = c; }

LineStatus read_line(char* buf) {
  size_t n = 0;
  // Characters typed past kMaxLine: not kept or echoed, but counted, so that backspacing over
  // them brings the line back within the limit (they are the first a backspace takes away).
  size_t beyond = 0;
  for (;;) {
    int c = g_unread;
    g_unread = EOF;
    if (c == EOF) c = getchar();
    if (c == EOF) return LineStatus::kEndOfInput;
    if (c == 0) {
      g_frame_bytes_left = g_frame_bytes_left > 0 ? 0 : htx::fw::kPacketMaxLine;
      continue;
    }
    if (g_frame_bytes_left > 0) {
      --g_frame_bytes_left;
      continue;
    }
    const bool lf_after_cr = g_after_cr && c == '\n';
    g_after_cr = c == '\r';
    if (lf_after_cr) continue;
    if (c == '\r' || c == '\n') {
      fputs("\r\n", stdout);
      buf[n] = '\0';
      if (htx::hal::uart_take_overrun()) return LineStatus::kOverrun;
      if (htx::hal::uart_take_frame_error()) return LineStatus::kGarbled;
      return beyond > 0 ? LineStatus::kTooLong : LineStatus::kLine;
    }
    if (c == kCtrlC) {
      fputs("^C\r\n", stdout);
      n = 0;
      beyond = 0;
      buf[0] = '\0';
      return LineStatus::kLine;
    }
    if (c == kBackspace || c == kDelete) {
      if (beyond > 0) {
        --beyond;
      } else if (n > 0) {
        --n;
        fputs("\b \b", stdout);
      }
      continue;
    }
    if (c < 0x20 || c > 0x7E) continue;  // other control bytes and non-ASCII are ignored
    if (n == kMaxLine) {
      ++beyond;
      continue;
    }
    buf[n++] = static_cast<char>(c);
    putchar(c);
  }
}

}  // namespace console_app
