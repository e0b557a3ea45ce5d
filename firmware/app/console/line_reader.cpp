#include "line_reader.hpp"

#include <stdio.h>

#include "htx/hal/uart.h"

namespace console_app {

namespace {
constexpr int kCtrlC = 0x03;
constexpr int kBackspace = 0x08;
constexpr int kDelete = 0x7F;
bool g_after_cr = false;  // swallow the LF of a CR LF pair
int g_unread = EOF;       // a byte given back by unread_byte
}  // namespace

void unread_byte(int c) { g_unread = c; }

LineStatus read_line(char* buf) {
  size_t n = 0;
  bool too_long = false;
  for (;;) {
    int c = g_unread;
    g_unread = EOF;
    if (c == EOF) c = getchar();
    if (c == EOF) return LineStatus::kEndOfInput;
    const bool lf_after_cr = g_after_cr && c == '\n';
    g_after_cr = c == '\r';
    if (lf_after_cr) continue;
    if (c == '\r' || c == '\n') {
      fputs("\r\n", stdout);
      buf[n] = '\0';
      if (htx::hal::uart_take_overrun()) return LineStatus::kOverrun;
      return too_long ? LineStatus::kTooLong : LineStatus::kLine;
    }
    if (c == kCtrlC) {
      fputs("^C\r\n", stdout);
      n = 0;
      too_long = false;
      buf[0] = '\0';
      return LineStatus::kLine;
    }
    if (c == kBackspace || c == kDelete) {
      if (n > 0) {
        --n;
        fputs("\b \b", stdout);
      }
      continue;
    }
    if (c < 0x20 || c > 0x7E) continue;  // other control bytes and non-ASCII are ignored
    if (n == kMaxLine) {
      too_long = true;
      continue;
    }
    buf[n++] = static_cast<char>(c);
    putchar(c);
  }
}

}  // namespace console_app
