// SB SH SW at every offset they allow: only the addressed lanes change.
#include "htx_test.h"
// Fill the scratch word with a known pattern, store, read the whole word back.
#define ST(num, inst, expected, value, off)                              \
  TEST_CASE(num, a1, expected, la a0, sdata; li a2, 0xa5a5a5a5; sw a2, 0(a0); sw a2, 4(a0); \
            li a3, value; inst a3, off(a0); lw a1, ((off) & ~3)(a0))
TEST_BEGIN
  ST(1, sw, 0x12345678, 0x12345678, 0)
  ST(2, sb, 0xa5a5a5ef, 0xdeadbeef, 0)
  ST(3, sb, 0xa5a5efa5, 0xdeadbeef, 1)
  ST(4, sb, 0xa5efa5a5, 0xdeadbeef, 2)
  ST(5, sb, 0xefa5a5a5, 0xdeadbeef, 3)
  ST(6, sh, 0xa5a5beef, 0xdeadbeef, 0)
  ST(7, sh, 0xbeefa5a5, 0xdeadbeef, 2)
  ST(8, sw, 0xcafef00d, 0xcafef00d, 4)
  ST(9, sb, 0x00a5a5a5, 0x00000000, 7)
  ST(10, sh, 0xa5a50000, 0x00000000, 4)
  // Store then load of the same bytes right away, with sign extension on the way back.
  TEST_CASE(11, a1, 0xffffff80, la a0, sdata; li a2, 0x180; sb a2, 1(a0); lb a1, 1(a0))
  TEST_CASE(12, a1, 0x00008001, la a0, sdata; li a2, 0x18001; sh a2, 2(a0); lhu a1, 2(a0))
  // Negative offset.
  TEST_CASE(13, a1, 0x5a5a5a5a, la a0, sdata; addi a0, a0, 8; li a2, 0x5a5a5a5a; sw a2, -8(a0);
            lw a1, -8(a0))
  // Store data produced by the previous instruction, address by the one before.
  TEST_CASE(14, a1, 0x00000124, la a0, sdata; li a2, 0x123; addi a2, a2, 1; sw a2, 0(a0); lw a1, 0(a0))
TEST_END
  .data
  .balign 8
sdata:
  .word 0, 0
