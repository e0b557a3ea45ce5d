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

// setup_cases.hpp's checksum interface on the firmware's setup.
struct FirmwareSetup {
  const setupcheck::Config& c;
  htx::fw::RecipSetup recip;
  htx::fw::CoverageSetup coverage(const htx::fw::TriangleRecord& rec, int32_t width, int32_t height) const {
    htx::fw::CoverageSetup s;
    htx::fw::setup_coverage(rec, width, height, &s);
    return s;
  }
  htx::fw::RecipResult reciprocal(int64_t det) const { return htx::fw::reciprocal(recip, static_cast<uint64_t>(det)); }
  htx::fw::PlaneSetup plane(const htx::fw::CoverageSetup& s, int plane, htx::fw::RecipResult inv) const {
    htx::fw::Int128 v[3];
    for (int k = 0; k < 3; ++k) v[k] = htx::fw::i128_from(htx::fw::plane_value(s.rec.v[k], plane));
    return htx::fw::make_plane(s, v, inv, c.params.grad_frac_bits);
  }
  int64_t divide(int64_t num, uint32_t q) const {
    return htx::fw::divide_fixed(recip, htx::fw::i128_from(num), q, c.params.texcoord_frac_bits);
  }
};

}  // namespace

int main() {
  for (const setupcheck::Config& c : setupcheck::kConfigs) {
    htx::fw::recip_fill_table(c.params.recip.k, c.params.recip.g, g_table);
    htx::fw::RecipSetup recip = c.params.recip;
    recip.table = g_table;
    FirmwareSetup setup{c, recip};
    uint32_t drawn = 0;
    const uint32_t crc = setupcheck::checksum(c, setup, &drawn);
    printf("setupcheck %s triangles %lu drawn %lu checksum %08lx\n", c.name,
           static_cast<unsigned long>(setupcheck::kTriangles), static_cast<unsigned long>(drawn),
           static_cast<unsigned long>(crc));
  }
  return 0;
}
