// Triangle setup in firmware on the rv32im CPU (htx/fw/tri_setup.h), over setup_cases.hpp's
// triangles in each configuration, folded into one checksum per configuration that the host test
// (tests/system/setup_check_test.cpp) computes with the model:
//   setupcheck <config> triangles <n> drawn <d> checksum <x>
// (What setup costs in cycles is geombench's figure: this run also folds every result.)
#include <stdint.h>
#include <stdio.h>

#include "htx/fw/tri_setup.h"
#include "setup_cases.hpp"

namespace {

uint32_t g_table[1024];

}  // namespace

int main() {
  for (const setupcheck::Config& c : setupcheck::kConfigs) {
    htx::fw::recip_fill_table(c.recip_k, c.recip_g, g_table);
    const htx::fw::RecipSetup rp{c.recip_k, c.recip_g, c.recip_width, c.setup_steps, g_table};
    setupcheck::Lcg gen{2026};
    uint32_t crc = 0, drawn = 0;
    for (uint32_t i = 0; i < setupcheck::kTriangles; ++i) {
      const htx::fw::TriangleRecord rec = setupcheck::make_record(c, gen);
      htx::fw::CoverageSetup s;
      htx::fw::setup_coverage(rec, c.width, c.height, &s);
      crc = setupcheck::fold(crc, static_cast<uint64_t>(s.det));
      if (s.det == 0) continue;
      crc = setupcheck::fold(crc, s.empty ? 1 : 0);
      crc = setupcheck::fold(crc, static_cast<uint64_t>(s.x_lo) ^ (static_cast<uint64_t>(s.x_hi) << 32));
      crc = setupcheck::fold(crc, static_cast<uint64_t>(s.y_lo) ^ (static_cast<uint64_t>(s.y_hi) << 32));
      for (const htx::fw::SetupEdge& e : s.edges) {
        crc = setupcheck::fold(crc, static_cast<uint64_t>(e.a));
        crc = setupcheck::fold(crc, static_cast<uint64_t>(e.b));
        crc = setupcheck::fold(crc, static_cast<uint64_t>(e.threshold));
      }
      if (s.empty) continue;
      const htx::fw::RecipResult inv = htx::fw::reciprocal(rp, static_cast<uint64_t>(s.det));
      crc = setupcheck::fold(crc, inv.value);
      crc = setupcheck::fold(crc, static_cast<uint64_t>(inv.shift));
      for (int a = 0; a < 8; ++a) {
        htx::fw::Int128 v[3];
        for (int k = 0; k < 3; ++k) v[k] = htx::fw::i128_from(setupcheck::attribute(s.rec.v[k], a));
        const htx::fw::PlaneSetup p = htx::fw::make_plane(s, v, inv, c.grad_frac_bits);
        const htx::fw::Int128 words[3] = {p.base, p.gx, p.gy};
        for (const htx::fw::Int128& w : words) {
          crc = setupcheck::fold(crc, w.lo);
          crc = setupcheck::fold(crc, w.hi);
        }
      }
      for (const htx::fw::VertexRecord& v : s.rec.v) {
        const int64_t nums[2] = {v.uq, v.vq};
        for (const int64_t n : nums) {
          crc = setupcheck::fold(crc, static_cast<uint64_t>(
                                          htx::fw::divide_fixed(rp, htx::fw::i128_from(n), v.q, c.texcoord_frac_bits)));
        }
      }
      ++drawn;
    }
    printf("setupcheck %s triangles %lu drawn %lu checksum %08lx\n", c.name,
           static_cast<unsigned long>(setupcheck::kTriangles), static_cast<unsigned long>(drawn),
           static_cast<unsigned long>(crc));
  }
  return 0;
}
