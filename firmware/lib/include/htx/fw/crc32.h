// CRC-32 (IEEE 802.3: reflected polynomial 0xEDB88320, initial and final value 0xFFFFFFFF, as
// zlib's crc32), shared by the firmware (frame checksums, console packets) and the host tools.
// Freestanding C++17.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace htx::fw {

inline constexpr uint32_t kCrc32Init = 0xFFFFFFFFu;

// Adds bytes to a running CRC register (start from kCrc32Init; the checksum is ~register).
// A byte table (1 KiB, crc32.cpp).
uint32_t crc32_update(uint32_t reg, const uint8_t* data, size_t size);
uint32_t crc32_update_byte(uint32_t reg, uint8_t byte);

inline uint32_t crc32(const uint8_t* data, size_t size) { return ~crc32_update(kCrc32Init, data, size); }

}  // namespace htx::fw
