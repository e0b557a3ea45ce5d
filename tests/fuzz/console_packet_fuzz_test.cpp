// The console's packet and pixel decoders (firmware/lib), compiled here with the address and
// undefined-behaviour sanitizers, fed seeded random streams, and valid streams with random damage:
// no out-of-bounds access, no damaged packet taken for a good one (its CRC-32 would have to
// collide), every undamaged packet after the damage still decoded.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "htx/fw/console_packet.h"
#include "htx/fw/rle16.h"

namespace {

using namespace htx::fw;

TEST(ConsolePacketFuzz, RandomBytesNeverCrashTheDecoders) {
  std::mt19937 rng(20261203);
  PacketDecoder d;
  size_t ready = 0;
  for (int i = 0; i < 2'000'000; ++i) {
    // Zeros often enough that frames of every length end.
    const uint8_t b = rng() % 64 == 0 ? 0 : static_cast<uint8_t>(rng());
    Packet p;
    ready += packet_feed(&d, b, &p) == kPacketReady;
  }
  EXPECT_EQ(ready, 0u);  // random frames fail their CRC-32
  for (int i = 0; i < 20000; ++i) {
    std::vector<uint8_t> code(rng() % 300);
    for (uint8_t& b : code) b = static_cast<uint8_t>(rng());
    std::vector<uint16_t> out(rng() % 400);
    const long n = rle16_decode(code.data(), code.size(), out.data(), out.size());
    ASSERT_LE(n, static_cast<long>(out.size()));
  }
}

TEST(ConsolePacketFuzz, DamagedStreamsLoseOnlyTheDamagedPackets) {
  std::mt19937 rng(7);
  for (int round = 0; round < 2000; ++round) {
    std::vector<std::vector<uint8_t>> sent;
    std::vector<uint8_t> stream;
    std::vector<size_t> starts;
    for (int k = 0; k < 8; ++k) {
      std::vector<uint8_t> payload(rng() % (kPacketMaxPayload + 1));
      for (uint8_t& b : payload) b = rng() % 4 == 0 ? 0 : static_cast<uint8_t>(rng());
      uint8_t line[kPacketMaxLine];
      const size_t n = packet_encode(kPacketFrameData, static_cast<uint8_t>(k), payload.data(), payload.size(), line);
      starts.push_back(stream.size());
      stream.insert(stream.end(), line, line + n);
      sent.push_back(payload);
    }
    // Damage one packet: flip, drop or insert a byte strictly inside it.
    const int victim = static_cast<int>(rng() % 8);
    const size_t lo = starts[victim] + 1, hi = (victim == 7 ? stream.size() : starts[victim + 1]) - 1;
    const size_t at = lo + rng() % (hi - lo);
    switch (rng() % 3) {
      case 0: stream[at] ^= static_cast<uint8_t>(1 + rng() % 255); break;
      case 1: stream.erase(stream.begin() + static_cast<long>(at)); break;
      default: stream.insert(stream.begin() + static_cast<long>(at), static_cast<uint8_t>(1 + rng() % 255)); break;
    }
    PacketDecoder d;
    std::vector<int> got;
    for (uint8_t b : stream) {
      Packet p;
      if (packet_feed(&d, b, &p) != kPacketReady) continue;
      ASSERT_LT(p.seq, 8);
      ASSERT_EQ(std::vector<uint8_t>(p.payload, p.payload + p.len), sent[p.seq]) << "round " << round;
      got.push_back(p.seq);
    }
    std::vector<int> expected;
    for (int k = 0; k < 8; ++k)
      if (k != victim) expected.push_back(k);
    EXPECT_EQ(got, expected) << "round " << round << " victim " << victim;
  }
}

}  // namespace
