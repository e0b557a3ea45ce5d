// The generated registers (htx_regs.h) as every HAL driver and firmware source sees them. The
// backend header comes first: it is found on the include path of the build (hal/target/include for
// the SoC, hal/sim/include for the host simulation) and may redefine the register word, the access
// qualifiers and where each register block lives, so `HTX_RASTER->FIFO = word;` reads the same
// everywhere. Include this header, never htx_regs.h directly.
#pragma once

#include "htx/hal/backend.h"
#include "htx_regs.h"
