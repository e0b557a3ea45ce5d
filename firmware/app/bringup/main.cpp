// Bring-up firmware for a board that holds the CPU and its peripherals but not the whole SoC (the
// iCEBreaker's 4 KiB of RAM, docs/boards.md): names the SoC and its clock, then sends back every
// byte it receives (a carriage return as CR LF). No printf, so that it fits with its stack.
#include <stdint.h>
#include <stdio.h>

#include "htx_regs.h"

namespace {

void put_text(const char* s) {
  while (*s) putchar(*s++);
}

void put_hex(uint32_t v) {
  for (int shift = 28; shift >= 0; shift -= 4) putchar("0123456789abcdef"[(v >> shift) & 0xFu]);
}

void put_decimal(uint32_t v) {
  char digits[10];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10u);
    v /= 10u;
  } while (v != 0);
  while (n > 0) putchar(digits[--n]);
}

}  // namespace

int main() {
  put_text("hypertex bring-up: soc ");
  put_hex(HTX_SYSCTRL->ID);
  put_text(" at ");
  put_decimal(HTX_SYSCTRL->CLOCK_HZ);
  put_text(" Hz. Type; it comes back.\r\n");
  for (;;) {
    const int c = getchar();
    if (c == EOF) continue;
    putchar(c);
    if (c == '\r') putchar('\n');
  }
}
