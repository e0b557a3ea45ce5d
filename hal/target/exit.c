/* _exit: the end of every firmware run (exit(), a return from main, a trap report). In simulation
 * SYSCTRL.SIM_EXIT ends the run with the status; on a board that register is ignored and the CPU
 * stays here. The UART drains first, so the last bytes are on the wire before the SoC stops. */
#include <stdint.h>

#include "htx_regs.h"

void _exit(int status) {
  while (!(HTX_UART->STATUS & UART_STATUS_TX_IDLE_Msk)) {
  }
  HTX_SYSCTRL->SIM_EXIT = (uint32_t)status & SYSCTRL_SIM_EXIT_CODE_Msk;
  for (;;) {
  }
}
