// Every constant of the generated SV register packages has the same value in the generated C header:
// offsets (as #defines and as struct member offsets), field positions, widths, masks and resets.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "htx_regs.h"

namespace {

struct Mismatch {
  std::string name;
  unsigned long long c_value, sv_value;
};

std::vector<Mismatch> run_checks(int& count) {
  std::vector<Mismatch> bad;
#define CHECK_EQ_C(expr, sv, label)                                            \
  do {                                                                         \
    ++count;                                                                   \
    const unsigned long long c_val = static_cast<unsigned long long>(expr);   \
    if (c_val != (sv)) bad.push_back({label, c_val, sv});                      \
  } while (0);
#include "regcheck_table.inc"
#undef CHECK_EQ_C
  return bad;
}

TEST(RegsAgree, HeaderMatchesSvPackages) {
  int count = 0;
  const auto bad = run_checks(count);
  EXPECT_GT(count, 10) << "too few constants checked: is the table empty?";
  for (const auto& m : bad)
    ADD_FAILURE() << m.name << ": C header says " << m.c_value << ", SV package says " << m.sv_value;
}

}  // namespace
