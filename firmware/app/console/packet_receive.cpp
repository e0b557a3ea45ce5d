#include "packet_receive.hpp"

#include <stdio.h>

#include "htx/fw/console_packet.h"
#include "htx/fw/crc32.h"
#include "htx/hal/uart.h"
#include "packet_out.hpp"
#include "scene_store.hpp"

namespace console_app {

namespace {

// About 10 s of silence at 12 MHz: the host sends the next packet as soon as it has our answer.
constexpr uint32_t kSilencePolls = 10'000'000;

void answer(uint8_t type, uint8_t seq) { send_packet(type, 0, &seq, 1); }

// Packets into the staging bytes until `size` have come, each answered (Ack, or Nak to have it
// again); false with the error printed when the host abandons it, the line falls silent or the
// checksum does not match.
bool receive_into_staging(uint32_t size, uint32_t crc32, const char* what) {
  uint8_t* staging = staging_bytes();
  htx::fw::PacketDecoder decoder;
  uint32_t received = 0;
  uint8_t expect = 0;
  // A CR or LF before the first packet is the command line's tail (the LF of a CR LF line end), not
  // a packet: a frame of it would be answered with a Nak the host did not ask for, putting its
  // answers a packet out of step. (Any other byte there is a packet whose leading zero was lost:
  // its frame is damaged, and the Nak asks for it again.)
  bool framed = false;
  while (received < size) {
    const int c = htx::hal::uart_get(kSilencePolls);
    if (c < 0) {
      printf("error: upload timed out after %lu of %lu bytes; the %s is unchanged\r\n",
             static_cast<unsigned long>(received), static_cast<unsigned long>(size), what);
      return false;
    }
    if (!framed && (c == '\r' || c == '\n')) continue;
    framed = true;
    htx::fw::Packet p;
    const htx::fw::PacketStatus st = htx::fw::packet_feed(&decoder, static_cast<uint8_t>(c), &p);
    if (st == htx::fw::kPacketNone) continue;
    if (st != htx::fw::kPacketReady) {
      answer(htx::fw::kPacketNak, expect);  // damaged: ask for it again
      continue;
    }
    if (p.type == htx::fw::kPacketAbort) {
      printf("error: the host abandoned the upload; the %s is unchanged\r\n", what);
      return false;
    }
    if (p.type != htx::fw::kPacketSceneData) {
      answer(htx::fw::kPacketNak, expect);
      continue;
    }
    if (p.seq == static_cast<uint8_t>(expect - 1) && received > 0) {
      answer(htx::fw::kPacketAck, p.seq);  // a repeat: our acknowledgement was lost
      continue;
    }
    if (p.seq != expect || received + p.len > size) {
      answer(htx::fw::kPacketNak, expect);
      continue;
    }
    for (uint32_t i = 0; i < p.len; ++i) staging[received + i] = p.payload[i];
    received += p.len;
    answer(htx::fw::kPacketAck, expect++);
  }
  if (htx::fw::crc32(staging, size) != crc32) {
    printf("error: the %s's CRC-32 does not match; the %s is unchanged\r\n", what, what);
    return false;
  }
  return true;
}

}  // namespace

bool receive_packets(uint32_t size, uint32_t crc32, uint32_t capacity, const char* what) {
  if (size == 0 || size > capacity) {
    printf("error: a %s of %lu bytes does not fit the store (1..%lu)\r\n", what, static_cast<unsigned long>(size),
           static_cast<unsigned long>(capacity));
    return false;
  }
  htx::hal::uart_clear_rx_errors();  // from before the upload: packets have their own checks
  printf("ready\r\n");
  const bool ok = receive_into_staging(size, crc32, what);
  // Bytes the receive FIFO lost during the transfer were packets', sent again and taken: the flag
  // must not make the line reader drop the next command.
  htx::hal::uart_clear_rx_errors();
  return ok;
}

}  // namespace console_app
