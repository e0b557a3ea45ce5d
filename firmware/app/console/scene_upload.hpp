// `upload SIZE CRC32`: receives a packed scene as packets (htx/fw/console_packet.h), acknowledging
// each, and commits it when it is complete, has the announced CRC-32 and is valid (docs/console.md).
#pragma once

#include <stdint.h>

namespace console_app {

void receive_scene(uint32_t size, uint32_t crc32);

}  // namespace console_app
