// The receiving side of an upload (docs/console.md, "Scene upload"): after `ready`, packets of the
// announced size are taken in order into the staging buffer, each acknowledged or refused, until
// all have arrived and the whole has the announced CRC-32. Shared by `upload` and `texture`.
#pragma once

#include <stdint.h>

namespace console_app {

// Receives `size` bytes (1..capacity) into staging_bytes() (scene_store.hpp). Returns true when
// they all arrived with the announced CRC-32; otherwise prints `error: ...; the <what> is
// unchanged` (or that the size does not fit) and returns false.
bool receive_packets(uint32_t size, uint32_t crc32, uint32_t capacity, const char* what);

}  // namespace console_app
