// LB LH LW LBU LHU at every byte offset they allow: lane selection, sign and zero extension,
// negative and positive offsets.
#include "htx_test.h"
TEST_BEGIN
#define LD(num, inst, expected, off) TEST_CASE(num, a1, expected, la a0, ldata; inst a1, off(a0))
  LD(1, lw, 0x80017ffe, 0)
  LD(2, lw, 0x7f02ff81, 4)
  LD(3, lb, 0xfffffffe, 0)
  LD(4, lb, 0x0000007f, 1)
  LD(5, lb, 0x00000001, 2)
  LD(6, lb, 0xffffff80, 3)
  LD(7, lbu, 0x000000fe, 0)
  LD(8, lbu, 0x0000007f, 1)
  LD(9, lbu, 0x00000001, 2)
  LD(10, lbu, 0x00000080, 3)
  LD(11, lh, 0x00007ffe, 0)
  LD(12, lh, 0xffff8001, 2)
  LD(13, lhu, 0x00007ffe, 0)
  LD(14, lhu, 0x00008001, 2)
  LD(15, lh, 0xffffff81, 4)
  LD(16, lh, 0x00007f02, 6)
  LD(17, lhu, 0x0000ff81, 4)
  LD(18, lb, 0xffffff81, 4)
  LD(19, lb, 0xffffffff, 5)
  LD(20, lb, 0x00000002, 6)
  LD(21, lbu, 0x000000ff, 5)
  // Negative offsets from a base past the data.
  TEST_CASE(22, a1, 0x7f02ff81, la a0, ldata; addi a0, a0, 8; lw a1, -4(a0))
  TEST_CASE(23, a1, 0xffffff80, la a0, ldata; addi a0, a0, 8; lb a1, -5(a0))
  TEST_CASE(24, a1, 0xffff8001, la a0, ldata; addi a0, a0, 8; lh a1, -6(a0))
  // Load into x0 is discarded.
  TEST_CASE(25, a1, 0, la a0, ldata; lw x0, 0(a0); mv a1, x0)
  // Back-to-back loads, the second using the first as its address.
  TEST_CASE(26, a1, 0x80017ffe, la a0, lptr; lw a2, 0(a0); lw a1, 0(a2))
TEST_END
  .data
  .balign 4
ldata:
  .word 0x80017ffe
  .word 0x7f02ff81
lptr:
  .word ldata
