// LUI and AUIPC.
#include "htx_test.h"
TEST_BEGIN
  TEST_CASE(1, a0, 0x00000000, lui a0, 0)
  TEST_CASE(2, a0, 0xfffff000, lui a0, 0xfffff)
  TEST_CASE(3, a0, 0x80000000, lui a0, 0x80000)
  TEST_CASE(4, a0, 0x7ffff000, lui a0, 0x7ffff)
  TEST_CASE(5, a0, 0x12345678, lui a0, 0x12345; addi a0, a0, 0x678)
  // AUIPC adds to its own address.
  TEST_CASE(6, a2, 0, 1: auipc a0, 0; la a1, 1b; sub a2, a0, a1)
  TEST_CASE(7, a2, 0x00001000, 1: auipc a0, 1; la a1, 1b; sub a2, a0, a1)
  TEST_CASE(8, a2, 0xfffff000, 1: auipc a0, 0xfffff; la a1, 1b; sub a2, a0, a1)
  TEST_CASE(9, a2, 0x80000000, 1: auipc a0, 0x80000; la a1, 1b; sub a2, a0, a1)
  TEST_CASE(10, a0, 0, lui x0, 0x12345; auipc x0, 7; mv a0, x0)
TEST_END
