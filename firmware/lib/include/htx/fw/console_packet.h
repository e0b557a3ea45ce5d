// Binary packets of the serial console (docs/console.md), shared by the firmware and the host.
// A packet's body is: type (1 byte), sequence number (1), payload length (2, little-endian), the
// payload, and the CRC-32 (crc32.h, 4 bytes, little-endian) of everything before it. On the line
// the body is COBS-encoded (no zero byte inside) and framed by a zero byte before and after, so a
// receiver finds the next packet after any garbage and text never looks like one.
// Freestanding C++17.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace htx::fw {

inline constexpr size_t kPacketMaxPayload = 240;
inline constexpr size_t kPacketHeader = 4;  // type, sequence, length
inline constexpr size_t kPacketMaxBody = kPacketHeader + kPacketMaxPayload + 4;
// COBS adds one byte per 254 (one here); plus the two framing zeros.
inline constexpr size_t kPacketMaxLine = kPacketMaxBody + 1 + 2;

// Packet types of a frame download (`grab`): one FrameInfo, FrameData packets with the run-length
// coded pixels (rle16.h) in order, one FrameEnd.
enum PacketType : uint8_t {
  kPacketFrameInfo = 'I',  // u16 width, u16 height, u8 pixel format (0 = RGB565), u8 coding (1 = RLE16),
                           // u32 CRC-32 of the raw pixels (two bytes each, low first, row by row)
  kPacketFrameData = 'D',  // the next bytes of the coded pixels
  kPacketFrameEnd = 'E',   // u32 number of FrameData packets, u32 coded bytes in all
  // A scene upload (`upload SIZE CRC32`): the host sends SceneData packets with sequence numbers
  // 0, 1, ... (mod 256) and waits for each to be answered: Ack (u8: the sequence number taken) or
  // Nak (u8: the sequence number wanted). Abort ends the upload with the scene unchanged.
  kPacketSceneData = 'S',  // the next bytes of a packed scene or texture (htx/render/scene_pack.h, texture_pack.h)
  kPacketAck = 'A',
  kPacketNak = 'N',
  kPacketAbort = 'X',
};

// Writes the framed packet to `out` (at least kPacketMaxLine bytes); returns the bytes written,
// or 0 when len > kPacketMaxPayload.
size_t packet_encode(uint8_t type, uint8_t seq, const uint8_t* payload, size_t len, uint8_t* out);

enum PacketStatus : uint8_t {
  kPacketNone,       // no packet ended with this byte
  kPacketReady,      // a valid packet: see the Packet
  kPacketBadCobs,    // the bytes between two zeros are not COBS
  kPacketTooLong,    // more bytes than any packet has before the closing zero
  kPacketBadLength,  // the length field disagrees with the body's size
  kPacketBadCrc,     // the checksum does not match
};

struct Packet {
  uint8_t type = 0, seq = 0;
  uint16_t len = 0;
  const uint8_t* payload = nullptr;  // valid until the next packet_feed
};

// A receiver's state: feed it every byte that arrives. Empty frames (two zeros in a row) are
// skipped silently; every other frame gives kPacketReady or an error, and the decoder is then
// ready for the next one, so one bad packet never corrupts the following ones.
struct PacketDecoder {
  uint8_t line[kPacketMaxBody + 2];
  uint8_t body[kPacketMaxBody + 2];
  size_t size = 0;
  bool overflow = false;
};

PacketStatus packet_feed(PacketDecoder* d, uint8_t byte, Packet* out);

inline void put_le16(uint8_t* p, uint32_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}
inline void put_le32(uint8_t* p, uint32_t v) {
  put_le16(p, v);
  put_le16(p + 2, v >> 16);
}
inline uint32_t get_le16(const uint8_t* p) { return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8); }
inline uint32_t get_le32(const uint8_t* p) { return get_le16(p) | (get_le16(p + 2) << 16); }

}  // namespace htx::fw
