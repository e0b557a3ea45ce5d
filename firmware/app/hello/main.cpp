// The smallest hypertex firmware: identifies the SoC over the UART and exits with status 0.
#include <stdio.h>

#include "htx_regs.h"

int main() {
  const uint32_t version = HTX_SYSCTRL->VERSION;
  printf("hello from hypertex: soc id %08lx version %lu.%lu.%lu, %lu Hz\n",
         static_cast<unsigned long>(HTX_SYSCTRL->ID),
         static_cast<unsigned long>((version & SYSCTRL_VERSION_MAJOR_Msk) >> SYSCTRL_VERSION_MAJOR_Pos),
         static_cast<unsigned long>((version & SYSCTRL_VERSION_MINOR_Msk) >> SYSCTRL_VERSION_MINOR_Pos),
         static_cast<unsigned long>((version & SYSCTRL_VERSION_PATCH_Msk) >> SYSCTRL_VERSION_PATCH_Pos),
         static_cast<unsigned long>(HTX_SYSCTRL->CLOCK_HZ));
  return 0;
}
