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

}  // namespace

bool receive_packets(uint32_t size, uint32_t crc32, uint32_t capacity, const char* what) {
  if (size == 0 || size > capacity) {
    printf("error: a %s of %lu bytes does not fit the store (1..%lu)\r\n", what, static_cast<unsigned long>(size),
           static_cast<unsigned long>(capacity));
    return false;
  }
  htx::hal::uart_take_overrun();  // from before the upload: packets have their own checks
  printf("ready\r\n");
  uint8_t* staging = staging_bytes();
  htx::fw::PacketDecoder decoder;
  uint32_t received = 0;
  uint8_t expect = 0;
  while (received < size) {
    const int c = htx::hal::uart_get(kSilencePolls);
    if (c < 0) {
      printf("error: upload timed out after %lu of %lu bytes; the %s is unchanged\r\n",
             static_cast<unsigned long>(received), static_cast<unsigned long>(size), what);
      return false;
    }
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

}  // namespace console_app
