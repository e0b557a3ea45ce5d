/* Reports an unexpected trap on the UART and ends the run with status 128 + mcause. */
#include <stdint.h>

#include "htx_regs.h"

void _exit(int status);

static void put_raw(char c) {
  HTX_UART->DATA = (uint8_t)c; /* a full TX FIFO stalls the write: nothing is lost */
}

static void put_str(const char *s) {
  while (*s) put_raw(*s++);
}

static void put_hex(uint32_t v) {
  for (int shift = 28; shift >= 0; shift -= 4) put_raw("0123456789abcdef"[(v >> shift) & 0xFu]);
}

void htx_trap_report(uint32_t mcause, uint32_t mepc, uint32_t mtval) {
  /* Raw UART writes: stdio may be what trapped. */
  put_str("\r\n*** trap: mcause ");
  put_hex(mcause);
  put_str(" mepc ");
  put_hex(mepc);
  put_str(" mtval ");
  put_hex(mtval);
  put_str("\r\n");
  _exit(128 + (int)(mcause & 0x7Fu));
}
