// TMDS as DVI 1.0 defines it (section 3.2.2), written from the specification's flow chart to check
// htx_tmds_encoder and to decode the board top's symbols: an 8-bit value becomes 10 bits, sent
// bit 0 first. Bits 0..7 are an XOR or XNOR chain of the data (bit 8 = 1 for XOR) chosen to
// minimise transitions; bit 9 = 1 inverts bits 0..7 to pull the running disparity back to zero.
#pragma once

#include <bit>
#include <cstdint>

namespace htx::video_test {

// The four control symbols, indexed by {C1, C0}.
inline constexpr uint16_t kControlSymbol[4] = {0b1101010100, 0b0010101011, 0b0101010100, 0b1010101011};

class TmdsEncoder {
 public:
  // One pixel clock: data when de, else the control bits {c1, c0}.
  uint16_t encode(bool de, uint8_t data, unsigned ctrl) {
    if (!de) {
      disparity_ = 0;
      return kControlSymbol[ctrl & 3];
    }
    const int ones = std::popcount(data);
    const bool use_xnor = ones > 4 || (ones == 4 && (data & 1) == 0);
    unsigned qm = data & 1;
    for (int i = 1; i < 8; ++i) {
      const unsigned prev = (qm >> (i - 1)) & 1, d = (data >> i) & 1;
      const unsigned bit = use_xnor ? !(prev ^ d) : (prev ^ d);
      qm |= bit << i;
    }
    const bool qm8 = !use_xnor;
    const int n1 = std::popcount(qm & 0xFFu), n0 = 8 - n1;
    uint16_t out;
    if (disparity_ == 0 || n1 == n0) {
      out = static_cast<uint16_t>(((qm8 ? 0u : 1u) << 9) | (qm8 ? 1u << 8 : 0u) | (qm8 ? qm : (~qm & 0xFFu)));
      disparity_ += qm8 ? n1 - n0 : n0 - n1;
    } else if ((disparity_ > 0 && n1 > n0) || (disparity_ < 0 && n0 > n1)) {
      out = static_cast<uint16_t>((1u << 9) | (qm8 ? 1u << 8 : 0u) | (~qm & 0xFFu));
      disparity_ += 2 * (qm8 ? 1 : 0) + n0 - n1;
    } else {
      out = static_cast<uint16_t>((qm8 ? 1u << 8 : 0u) | qm);
      disparity_ += -2 * (qm8 ? 0 : 1) + n1 - n0;
    }
    return out;
  }
  int disparity() const { return disparity_; }

 private:
  int disparity_ = 0;
};

struct TmdsSymbol {
  bool de = false;
  uint8_t data = 0;   // when de
  unsigned ctrl = 0;  // when !de: {C1, C0}
};

// What a symbol carries: one of the control symbols, else data (any other 10-bit word decodes as
// data, as a receiver in its data period reads it).
inline TmdsSymbol tmds_decode(uint16_t sym) {
  for (unsigned c = 0; c < 4; ++c) {
    if (sym == kControlSymbol[c]) return TmdsSymbol{false, 0, c};
  }
  unsigned q = sym & 0xFFu;
  if (sym & (1u << 9)) q = ~q & 0xFFu;
  const bool xor_chain = (sym >> 8) & 1;
  unsigned d = q & 1;
  for (int i = 1; i < 8; ++i) {
    const unsigned x = ((q >> i) ^ (q >> (i - 1))) & 1;
    d |= (xor_chain ? x : !x) << i;
  }
  return TmdsSymbol{true, static_cast<uint8_t>(d), 0};
}

// Ones minus zeros of a 10-bit symbol.
inline int tmds_balance(uint16_t sym) {
  return 2 * std::popcount(static_cast<unsigned>(sym & 0x3FFu)) - 10;
}

}  // namespace htx::video_test
