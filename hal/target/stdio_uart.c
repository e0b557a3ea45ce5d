/* picolibc stdio over the UART. picolibc asks the application for the stdin/stdout/stderr streams;
 * a full TX FIFO stalls the bus write, so putc never drops a byte. stdin blocks until a byte arrives. */
#include <stdio.h>

#include "htx_regs.h"

static int uart_putc(char c, FILE *file) {
  (void)file;
  HTX_UART->DATA = (uint8_t)c;
  return (uint8_t)c;
}

static int uart_getc(FILE *file) {
  (void)file;
  uint32_t word;
  do {
    word = HTX_UART->DATA;
  } while (word & UART_DATA_RX_EMPTY_Msk);
  return (int)(word & UART_DATA_BYTE_Msk);
}

static FILE uart_stream = FDEV_SETUP_STREAM(uart_putc, uart_getc, NULL, _FDEV_SETUP_RW);
FILE *const stdin = &uart_stream;
FILE *const stdout = &uart_stream;
FILE *const stderr = &uart_stream;
