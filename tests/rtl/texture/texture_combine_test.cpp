// The combine stage against the model's fragment rule (docs/model.md §8): every texel and colour
// channel pair for modulate, plus replace and untextured.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

#include "Vhtx_tex_combine.h"
#include "verilated.h"

namespace {

unsigned modulate8(unsigned a, unsigned b) {  // render_model.cpp's rule
  const unsigned x = a * b + 128;
  return (x + (x >> 8)) >> 8;
}

TEST(TextureCombine, EveryChannelPair) {
  auto ctx = std::make_unique<VerilatedContext>();
  auto top = std::make_unique<Vhtx_tex_combine>(ctx.get());
  uint64_t bad = 0;
  for (unsigned t = 0; t < 256; ++t)
    for (unsigned c = 0; c < 256; ++c) {
      // Each channel carries a different pair so the lanes are checked independently.
      const unsigned t4[4] = {t, c, (t + 77) & 255, 255 - t}, c4[4] = {c, t, 255 - c, (c + 13) & 255};
      uint32_t tex = 0, col = 0, mod = 0;
      for (int k = 0; k < 4; ++k) {
        tex |= t4[k] << (8 * k);
        col |= c4[k] << (8 * k);
        mod |= modulate8(t4[k], c4[k]) << (8 * k);
      }
      top->texel_i = tex;
      top->color_i = col;
      top->textured_i = 1;
      top->modulate_i = 1;
      top->eval();
      bad += top->rgba_o != mod;
      top->modulate_i = 0;
      top->eval();
      bad += top->rgba_o != tex;
      top->textured_i = 0;
      top->eval();
      bad += top->rgba_o != col;
    }
  EXPECT_EQ(bad, 0u);
  top->final();
}

}  // namespace
