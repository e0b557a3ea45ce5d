// UART driver (hw/regs/uart.json): bytes out and in, and waiting for the line to drain.
// Freestanding C++17, written once over the generated registers for every HAL backend.
#pragma once

#include <stdint.h>

#include "htx/hal/regs.h"

namespace htx::hal {

// Queues one byte. A full TX FIFO holds the bus write until there is room, so nothing is lost.
inline void uart_put(uint8_t byte) { HTX_UART->DATA = byte; }

inline void uart_write(const char* s) {
  while (*s) uart_put(static_cast<uint8_t>(*s++));
}

// Takes one received byte if there is one (returns false when the RX FIFO is empty).
inline bool uart_try_get(uint8_t* byte) {
  const uint32_t d = HTX_UART->DATA;
  if (d & UART_DATA_RX_EMPTY_Msk) return false;
  *byte = static_cast<uint8_t>((d & UART_DATA_BYTE_Msk) >> UART_DATA_BYTE_Pos);
  return true;
}

// Waits for a byte, polling at most max_polls times; returns -1 if none came.
inline int uart_get(uint32_t max_polls) {
  uint8_t b = 0;
  for (uint32_t i = 0; i < max_polls; ++i)
    if (uart_try_get(&b)) return b;
  return -1;
}

// Whether a byte arrived to a full RX FIFO and was dropped since the last call (RX_OVERRUN,
// cleared here).
inline bool uart_take_overrun() {
  if (!(HTX_UART->STATUS & UART_STATUS_RX_OVERRUN_Msk)) return false;
  HTX_UART->STATUS = UART_STATUS_RX_OVERRUN_Msk;
  return true;
}

// Clears both flags of a dropped received byte (RX_OVERRUN, RX_FRAME_ERR) in one store.
inline void uart_clear_rx_errors() { HTX_UART->STATUS = UART_STATUS_RX_OVERRUN_Msk | UART_STATUS_RX_FRAME_ERR_Msk; }

// Whether a byte arrived without its stop bit and was dropped since the last call (RX_FRAME_ERR,
// cleared here): the other end at another baud rate, or noise on the line.
inline bool uart_take_frame_error() {
  if (!(HTX_UART->STATUS & UART_STATUS_RX_FRAME_ERR_Msk)) return false;
  HTX_UART->STATUS = UART_STATUS_RX_FRAME_ERR_Msk;
  return true;
}

// Waits until every queued byte has left the shift register (TX_IDLE), polling at most max_polls
// times; returns false on a timeout.
inline bool uart_flush(uint32_t max_polls) {
  for (uint32_t i = 0; i < max_polls; ++i)
    if (HTX_UART->STATUS & UART_STATUS_TX_IDLE_Msk) return true;
  return false;
}

// The UART's clocks per bit (CTRL.DIVISOR; the UART takes at least 4).
inline uint32_t uart_divisor() { return (HTX_UART->CTRL & UART_CTRL_DIVISOR_Msk) >> UART_CTRL_DIVISOR_Pos; }
// Sets the clocks per bit; false, and nothing written, for a divisor the field cannot hold as it
// is (below 4, which the UART reads as 4, or above 65,535, whose low bits would be a faster rate).
inline bool uart_set_divisor(uint32_t divisor) {
  if (divisor < 4 || divisor > (UART_CTRL_DIVISOR_Msk >> UART_CTRL_DIVISOR_Pos)) return false;
  HTX_UART->CTRL = (HTX_UART->CTRL & ~UART_CTRL_DIVISOR_Msk) | (divisor << UART_CTRL_DIVISOR_Pos);
  return true;
}

}  // namespace htx::hal
