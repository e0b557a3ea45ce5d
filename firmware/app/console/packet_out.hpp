// Sends one framed packet (htx/fw/console_packet.h) over the UART: the frame download's packets
// and the upload's answers.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "htx/fw/console_packet.h"
#include "htx/hal/uart.h"

namespace console_app {

inline void send_packet(uint8_t type, uint8_t seq, const uint8_t* data, size_t len) {
  uint8_t line[htx::fw::kPacketMaxLine];
  const size_t n = htx::fw::packet_encode(type, seq, data, len, line);
  for (size_t i = 0; i < n; ++i) htx::hal::uart_put(line[i]);
}

}  // namespace console_app
