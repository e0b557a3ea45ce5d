// The filter multiplier (htx_tex_mul) in both forms, `*` (a DSP on iCE40) and ShiftAdd (eight
// gated additions in logic, the texture unit's option for a board without DSPs to spare, which
// no configuration builds today), against the product itself: every 9-bit value (the bilinear
// differences) with every weight, and 17-bit values (the vertical lerp's) from a fixed seed.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <random>

#include "Vhtx_tex_mul_dsp.h"
#include "Vhtx_tex_mul_shift_add.h"
#include "verilated.h"

namespace {

constexpr int kAw = 17;  // both models are Verilated with AW = 17

int64_t sext(uint64_t v, int bits) {
  const uint64_t m = uint64_t{1} << (bits - 1);
  return static_cast<int64_t>((v ^ m) - m);
}

template <typename Top>
uint64_t mismatches(Top* top, int64_t a, unsigned w) {
  top->a_i = static_cast<uint32_t>(a) & ((1u << kAw) - 1);
  top->w_i = w;
  top->eval();
  return sext(top->p_o, kAw + 9) != a * static_cast<int64_t>(w);
}

TEST(TextureMul, BothFormsGiveTheProduct) {
  auto ctx = std::make_unique<VerilatedContext>();
  auto dsp = std::make_unique<Vhtx_tex_mul_dsp>(ctx.get());
  auto shift_add = std::make_unique<Vhtx_tex_mul_shift_add>(ctx.get());
  uint64_t bad_dsp = 0, bad_shift_add = 0, checked = 0;
  for (int64_t a = -256; a < 256; ++a)
    for (unsigned w = 0; w < 256; ++w) {
      bad_dsp += mismatches(dsp.get(), a, w);
      bad_shift_add += mismatches(shift_add.get(), a, w);
      ++checked;
    }
  std::mt19937 rng(20261207u);
  std::uniform_int_distribution<int64_t> value(-(int64_t{1} << (kAw - 1)), (int64_t{1} << (kAw - 1)) - 1);
  for (int i = 0; i < 200000; ++i) {
    const int64_t a = value(rng);
    const unsigned w = rng() & 255u;
    bad_dsp += mismatches(dsp.get(), a, w);
    bad_shift_add += mismatches(shift_add.get(), a, w);
    ++checked;
  }
  for (const int64_t a : {-(int64_t{1} << (kAw - 1)), (int64_t{1} << (kAw - 1)) - 1})
    for (unsigned w : {0u, 1u, 128u, 255u}) {
      bad_dsp += mismatches(dsp.get(), a, w);
      bad_shift_add += mismatches(shift_add.get(), a, w);
      ++checked;
    }
  EXPECT_EQ(bad_dsp, 0u) << "of " << checked;
  EXPECT_EQ(bad_shift_add, 0u) << "of " << checked;
}

}  // namespace
