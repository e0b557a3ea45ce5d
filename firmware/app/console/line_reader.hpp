// A command line typed at the console: printable characters are echoed, backspace (BS or DEL)
// erases, Ctrl-C abandons the line, CR or LF ends it (an LF right after a CR is ignored). Bytes
// from a zero byte to the next (a packet frame, at most htx::fw::kPacketMaxLine bytes) are not
// text and are skipped: a packet the host sent again after an upload ended.
#pragma once

#include <stddef.h>

namespace console_app {

inline constexpr size_t kMaxLine = 96;

enum class LineStatus { kLine, kTooLong, kOverrun, kGarbled, kEndOfInput };

// Reads one line into buf (kMaxLine + 1 bytes, NUL-terminated). A line longer than kMaxLine is
// read to its end and reported as kTooLong (its text is dropped); a line during which the UART
// dropped received bytes (its 16-byte FIFO overran: text sent faster than the console reads it)
// is reported as kOverrun, since it may have lost characters; one during which a byte arrived
// without its stop bit (dropped by the UART: a terminal at another baud rate, or noise) as kGarbled.
LineStatus read_line(char* buf);

// Gives one received byte back: the next read_line takes it first (a key that stopped `spin` begins
// the next line instead of being lost).
void unread_byte(int c);

}  // namespace console_app
