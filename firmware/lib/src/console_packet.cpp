#include "htx/fw/console_packet.h"

#include "htx/fw/crc32.h"

namespace htx::fw {

namespace {

// COBS: each zero-free run of up to 254 bytes is sent after a code byte (its length + 1); a code
// below 0xFF implies a zero after its run, except at the very end.
size_t cobs_encode(const uint8_t* in, size_t n, uint8_t* out) {
  size_t code_at = 0, o = 1;
  uint8_t code = 1;
  for (size_t i = 0; i < n; ++i) {
    if (in[i] == 0) {
      out[code_at] = code;
      code_at = o++;
      code = 1;
      continue;
    }
    out[o++] = in[i];
    if (++code == 0xFF) {
      out[code_at] = code;
      code_at = o++;
      code = 1;
    }
  }
  out[code_at] = code;
  return o;
}

// Returns the decoded size, or -1 when the input is not COBS.
long cobs_decode(const uint8_t* in, size_t n, uint8_t* out) {
  size_t i = 0, o = 0;
  while (i < n) {
    const uint8_t code = in[i++];
    if (code == 0 || i + code - 1 > n) return -1;
    for (uint8_t k = 1; k < code; ++k) out[o++] = in[i++];
    if (code < 0xFF && i < n) out[o++] = 0;
  }
  return static_cast<long>(o);
}

}  // namespace

size_t packet_encode(uint8_t type, uint8_t seq, const uint8_t* payload, size_t len, uint8_t* out) {
  if (len > kPacketMaxPayload) return 0;
  uint8_t body[kPacketMaxBody];
  body[0] = type;
  body[1] = seq;
  put_le16(body + 2, static_cast<uint32_t>(len));
  for (size_t i = 0; i < len; ++i) body[kPacketHeader + i] = payload[i];
  put_le32(body + kPacketHeader + len, crc32(body, kPacketHeader + len));
  out[0] = 0;
  const size_t n = cobs_encode(body, kPacketHeader + len + 4, out + 1);
  out[1 + n] = 0;
  return n + 2;
}

PacketStatus packet_feed(PacketDecoder* d, uint8_t byte, Packet* out) {
  if (byte != 0) {
    if (d->size < sizeof d->line) d->line[d->size++] = byte;
    else d->overflow = true;
    return kPacketNone;
  }
  const size_t size = d->size;
  const bool overflow = d->overflow;
  d->size = 0;
  d->overflow = false;
  if (size == 0) return kPacketNone;
  if (overflow) return kPacketTooLong;
  const long n = cobs_decode(d->line, size, d->body);
  if (n < 0) return kPacketBadCobs;
  const size_t body = static_cast<size_t>(n);
  if (body < kPacketHeader + 4 || body > kPacketMaxBody) return kPacketBadLength;
  const uint32_t len = get_le16(d->body + 2);
  if (kPacketHeader + len + 4 != body) return kPacketBadLength;
  if (get_le32(d->body + kPacketHeader + len) != crc32(d->body, kPacketHeader + len)) return kPacketBadCrc;
  out->type = d->body[0];
  out->seq = d->body[1];
  out->len = static_cast<uint16_t>(len);
  out->payload = d->body + kPacketHeader;
  return kPacketReady;
}

}  // namespace htx::fw
