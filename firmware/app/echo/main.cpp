// Echo firmware: greets over the UART, then sends back every byte it receives. A carriage return
// is echoed as CR LF (terminals send CR for Enter); Ctrl-D says goodbye and exits with status 0.
#include <stdio.h>

#include "htx_regs.h"

namespace {
constexpr int kCtrlD = 0x04;
}

int main() {
  printf("hypertex echo: soc %08lx at %lu Hz. Type; Ctrl-D ends.\r\n",
         static_cast<unsigned long>(HTX_SYSCTRL->ID), static_cast<unsigned long>(HTX_SYSCTRL->CLOCK_HZ));
  for (;;) {
    const int c = getchar();
    if (c == EOF || c == kCtrlD) break;
    putchar(c);
    if (c == '\r') putchar('\n');
  }
  printf("\r\nbye\r\n");
  return 0;
}
