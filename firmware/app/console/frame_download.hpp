// `grab`: sends the colour window as packets (htx/fw/console_packet.h): FrameInfo, the RLE16-coded
// pixels in FrameData packets, FrameEnd (docs/console.md).
#pragma once

#include <stdint.h>

namespace console_app {

void send_frame(uint32_t width, uint32_t height);

}  // namespace console_app
