/* Target set-up before constructors and main: the UART runs at HTX_UART_BAUD whatever the SoC
 * clock (SYSCTRL.CLOCK_HZ), so a host terminal at that rate reads it on any board and in simulation. */
#include <stdint.h>

#include "htx_regs.h"

#ifndef HTX_UART_BAUD
#define HTX_UART_BAUD 115200u
#endif

void htx_target_init(void) {
  const uint32_t hz = HTX_SYSCTRL->CLOCK_HZ;
  uint32_t divisor = (hz + HTX_UART_BAUD / 2u) / HTX_UART_BAUD; /* nearest */
  if (divisor < 4u) divisor = 4u;
  if (divisor > 0xFFFFu) divisor = 0xFFFFu;
  HTX_UART->CTRL = (divisor << UART_CTRL_DIVISOR_Pos) & UART_CTRL_DIVISOR_Msk;
}
