// The console's wire format (firmware/lib: console_packet.h, rle16.h, crc32.h): packets survive the
// round trip for every payload length and content, a damaged packet is reported and never taken
// for a good one, the decoder finds the next packet after garbage, and the pixel code round-trips.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "htx/fw/console_packet.h"
#include "htx/fw/crc32.h"
#include "htx/fw/rle16.h"

namespace {

using namespace htx::fw;

std::vector<uint8_t> encode(uint8_t type, uint8_t seq, const std::vector<uint8_t>& payload) {
  std::vector<uint8_t> line(kPacketMaxLine);
  line.resize(packet_encode(type, seq, payload.data(), payload.size(), line.data()));
  return line;
}

// Feeds bytes; returns every status other than kPacketNone, with the good packets' payloads.
std::vector<PacketStatus> feed(PacketDecoder* d, const std::vector<uint8_t>& bytes,
                               std::vector<std::vector<uint8_t>>* payloads = nullptr) {
  std::vector<PacketStatus> out;
  for (uint8_t b : bytes) {
    Packet p;
    const PacketStatus s = packet_feed(d, b, &p);
    if (s == kPacketNone) continue;
    out.push_back(s);
    if (s == kPacketReady && payloads) payloads->emplace_back(p.payload, p.payload + p.len);
  }
  return out;
}

TEST(Crc32, MatchesTheStandardCheckValue) {
  const char* text = "123456789";
  EXPECT_EQ(crc32(reinterpret_cast<const uint8_t*>(text), 9), 0xCBF43926u);
}

// The table-driven update (two bytes a turn after an odd first one) against the polynomial applied
// a bit at a time, for every length to 70 and every split of a buffer into two updates.
TEST(Crc32, TableUpdateEqualsTheBitwiseDefinition) {
  auto bitwise = [](uint32_t reg, const uint8_t* data, size_t size) {
    for (size_t i = 0; i < size; ++i) {
      reg ^= data[i];
      for (int k = 0; k < 8; ++k) reg = (reg >> 1) ^ ((reg & 1u) ? 0xEDB88320u : 0u);
    }
    return reg;
  };
  std::mt19937 rng(5);
  std::vector<uint8_t> data(70);
  for (uint8_t& b : data) b = static_cast<uint8_t>(rng());
  for (size_t len = 0; len <= data.size(); ++len) {
    const uint32_t want = bitwise(kCrc32Init, data.data(), len);
    EXPECT_EQ(crc32_update(kCrc32Init, data.data(), len), want) << "len " << len;
    uint32_t by_byte = kCrc32Init;
    for (size_t i = 0; i < len; ++i) by_byte = crc32_update_byte(by_byte, data[i]);
    EXPECT_EQ(by_byte, want) << "len " << len;
    for (size_t cut = 0; cut <= len; ++cut) {
      const uint32_t split = crc32_update(crc32_update(kCrc32Init, data.data(), cut), data.data() + cut, len - cut);
      ASSERT_EQ(split, want) << "len " << len << " cut " << cut;
    }
  }
}

TEST(ConsolePacket, RoundTripsEveryLengthAndZeroRuns) {
  std::mt19937 rng(11);
  for (size_t len = 0; len <= kPacketMaxPayload; ++len) {
    std::vector<uint8_t> payload(len);
    for (uint8_t& b : payload) b = (rng() % 3 == 0) ? 0 : static_cast<uint8_t>(rng());
    const std::vector<uint8_t> line = encode(kPacketFrameData, static_cast<uint8_t>(len), payload);
    ASSERT_LE(line.size(), kPacketMaxLine);
    EXPECT_EQ(line.front(), 0);
    EXPECT_EQ(line.back(), 0);
    for (size_t i = 1; i + 1 < line.size(); ++i) ASSERT_NE(line[i], 0) << "len " << len;
    PacketDecoder d;
    Packet p;
    PacketStatus last = kPacketNone;
    for (uint8_t b : line) last = packet_feed(&d, b, &p);
    ASSERT_EQ(last, kPacketReady) << "len " << len;
    EXPECT_EQ(p.type, kPacketFrameData);
    EXPECT_EQ(p.seq, static_cast<uint8_t>(len));
    EXPECT_EQ(std::vector<uint8_t>(p.payload, p.payload + p.len), payload);
  }
  uint8_t out[kPacketMaxLine + 8];
  std::vector<uint8_t> big(kPacketMaxPayload + 1, 1);
  EXPECT_EQ(packet_encode(kPacketFrameData, 0, big.data(), big.size(), out), 0u);
}

TEST(ConsolePacket, EveryDamagedByteIsReportedAndTheNextPacketStillArrives) {
  const std::vector<uint8_t> payload = {1, 0, 2, 0, 0, 3, 250, 251, 0, 7};
  const std::vector<uint8_t> good = encode(kPacketFrameInfo, 5, payload);
  for (size_t i = 1; i + 1 < good.size(); ++i) {
    for (uint8_t flip : {0x01, 0x80, 0xFF}) {
      std::vector<uint8_t> bad = good;
      bad[i] ^= flip;
      bad.insert(bad.end(), good.begin(), good.end());
      PacketDecoder d;
      std::vector<std::vector<uint8_t>> payloads;
      const std::vector<PacketStatus> st = feed(&d, bad, &payloads);
      // The damaged packet yields an error (a zero byte in it may split it into two); then the good one.
      ASSERT_GE(st.size(), 2u) << "byte " << i;
      for (size_t k = 0; k + 1 < st.size(); ++k) EXPECT_NE(st[k], kPacketReady) << "byte " << i << " flip " << int(flip);
      EXPECT_EQ(st.back(), kPacketReady) << "byte " << i;
      ASSERT_FALSE(payloads.empty());
      EXPECT_EQ(payloads.back(), payload);
    }
  }
}

TEST(ConsolePacket, GarbageAndOverlongFramesAreReportedNotTaken) {
  PacketDecoder d;
  std::vector<uint8_t> junk(1000, 0x41);  // a long line without a zero
  junk.push_back(0);
  EXPECT_EQ(feed(&d, junk), (std::vector<PacketStatus>{kPacketTooLong}));
  // Text before a packet: the first zero ends the text as a bad frame, the packet follows intact.
  std::vector<uint8_t> stream = {'h', 'i', '\r', '\n'};
  const std::vector<uint8_t> good = encode(kPacketFrameEnd, 1, {1, 2, 3, 4, 5, 6, 7, 8});
  stream.insert(stream.end(), good.begin(), good.end());
  const std::vector<PacketStatus> st = feed(&d, stream);
  ASSERT_EQ(st.size(), 2u);
  EXPECT_NE(st[0], kPacketReady);
  EXPECT_EQ(st[1], kPacketReady);
  // Two zeros in a row are an empty frame, skipped silently.
  EXPECT_TRUE(feed(&d, {0, 0, 0}).empty());
}

std::vector<uint16_t> roundtrip(const std::vector<uint16_t>& px) {
  std::vector<uint8_t> code(rle16_max_size(px.size()));
  code.resize(rle16_encode(px.data(), px.size(), code.data()));
  std::vector<uint16_t> back(px.size());
  EXPECT_EQ(rle16_decode(code.data(), code.size(), back.data(), back.size()), static_cast<long>(px.size()));
  return back;
}

TEST(Rle16, RoundTripsRunsLiteralsAndTheirLimits) {
  std::mt19937 rng(3);
  for (size_t n : {0u, 1u, 2u, 127u, 128u, 129u, 130u, 131u, 257u, 1000u}) {
    std::vector<uint16_t> same(n, 0x1234), alternating(n), mixed(n);
    for (size_t i = 0; i < n; ++i) {
      alternating[i] = static_cast<uint16_t>(i & 1 ? 0xFFFF : 0);
      mixed[i] = static_cast<uint16_t>(rng() % 4 == 0 ? rng() : (i / 7) * 31);
    }
    EXPECT_EQ(roundtrip(same), same) << n;
    EXPECT_EQ(roundtrip(alternating), alternating) << n;
    EXPECT_EQ(roundtrip(mixed), mixed) << n;
  }
  // A flat row of 160 pixels takes two runs: 6 bytes.
  std::vector<uint16_t> row(160, 0x1234);
  std::vector<uint8_t> code(rle16_max_size(row.size()));
  EXPECT_EQ(rle16_encode(row.data(), row.size(), code.data()), 6u);
}

TEST(Rle16, RefusesTruncatedCodeAndOverflow) {
  std::vector<uint16_t> out(4);
  const uint8_t run[] = {0x80 + 3, 0x34, 0x12};  // five copies
  EXPECT_EQ(rle16_decode(run, sizeof run, out.data(), 4), -1);
  EXPECT_EQ(rle16_decode(run, 2, out.data(), 4), -1);
  const uint8_t literal[] = {2, 1, 0, 2, 0};  // three pixels announced, two present
  EXPECT_EQ(rle16_decode(literal, sizeof literal, out.data(), 4), -1);
}

}  // namespace
