// Multiply fusion (docs/cpu.md): a MUL-class instruction right behind another with the same source
// registers, whose destination is neither source, reads the other half of the product the unit
// already holds. Checks both results of every ordered pair, and the cases that must multiply
// again: a source overwritten by the first, a source changed in between, swapped sources,
// differing signedness. Expected values follow the M extension's definitions (kept as literals).
#include "htx_test.h"
TEST_BEGIN
  la s0, mdata
  // Every ordered pair of MUL-class instructions on the same sources, both operands negative
  // (the pairs whose signedness differs must not share the product).
  TEST_CASE(1, a2, 0xae908393, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; mul a3, a0, a1)
  TEST_CASE(2, a3, 0xae908393, nop)
  TEST_CASE(3, a2, 0xae908393, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; mulh a3, a0, a1)
  TEST_CASE(4, a3, 0x05fadeb2, nop)
  TEST_CASE(5, a2, 0xae908393, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; mulhsu a3, a0, a1)
  TEST_CASE(6, a3, 0xa0b7bda3, nop)
  TEST_CASE(7, a2, 0xae908393, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; mulhu a3, a0, a1)
  TEST_CASE(8, a3, 0x91999066, nop)
  TEST_CASE(9, a2, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulh a2, a0, a1; mul a3, a0, a1)
  TEST_CASE(10, a3, 0xae908393, nop)
  TEST_CASE(11, a2, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulh a2, a0, a1; mulh a3, a0, a1)
  TEST_CASE(12, a3, 0x05fadeb2, nop)
  TEST_CASE(13, a2, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulh a2, a0, a1; mulhsu a3, a0, a1)
  TEST_CASE(14, a3, 0xa0b7bda3, nop)
  TEST_CASE(15, a2, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulh a2, a0, a1; mulhu a3, a0, a1)
  TEST_CASE(16, a3, 0x91999066, nop)
  TEST_CASE(17, a2, 0xa0b7bda3, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhsu a2, a0, a1; mul a3, a0, a1)
  TEST_CASE(18, a3, 0xae908393, nop)
  TEST_CASE(19, a2, 0xa0b7bda3, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhsu a2, a0, a1; mulh a3, a0, a1)
  TEST_CASE(20, a3, 0x05fadeb2, nop)
  TEST_CASE(21, a2, 0xa0b7bda3, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhsu a2, a0, a1; mulhsu a3, a0, a1)
  TEST_CASE(22, a3, 0xa0b7bda3, nop)
  TEST_CASE(23, a2, 0xa0b7bda3, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhsu a2, a0, a1; mulhu a3, a0, a1)
  TEST_CASE(24, a3, 0x91999066, nop)
  TEST_CASE(25, a2, 0x91999066, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhu a2, a0, a1; mul a3, a0, a1)
  TEST_CASE(26, a3, 0xae908393, nop)
  TEST_CASE(27, a2, 0x91999066, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhu a2, a0, a1; mulh a3, a0, a1)
  TEST_CASE(28, a3, 0x05fadeb2, nop)
  TEST_CASE(29, a2, 0x91999066, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhu a2, a0, a1; mulhsu a3, a0, a1)
  TEST_CASE(30, a3, 0xa0b7bda3, nop)
  TEST_CASE(31, a2, 0x91999066, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhu a2, a0, a1; mulhu a3, a0, a1)
  TEST_CASE(32, a3, 0x91999066, nop)
  // Mixed signs; MULHSU with the sources swapped is a different product.
  TEST_CASE(33, a3, 0x3fffffff, li a0, 0x80000003; li a1, 0x7ffffffd; mulhsu a2, a0, a1; mulhsu a3, a1, a0)
  TEST_CASE(34, a2, 0xc0000002, nop)
  TEST_CASE(35, a3, 0xc0000002, li a0, 0x80000003; li a1, 0x7ffffffd; mul a2, a0, a1; mulh a3, a0, a1)
  TEST_CASE(36, a3, 0x3fffffff, li a0, 0x80000003; li a1, 0x7ffffffd; mulhu a2, a0, a1; mulhu a3, a0, a1)
  // The first one's destination is a source of the second: the second multiplies again.
  TEST_CASE(37, a3, 0x04cf21be, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a0, a0, a1; mulh a3, a0, a1)
  TEST_CASE(38, a3, 0x039d5367, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulh a1, a0, a1; mulhu a3, a0, a1)
  // A destination of x0 is not written, so the second may share the product.
  TEST_CASE(39, a3, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul x0, a0, a1; mulh a3, a0, a1)
  // The same register as both sources.
  TEST_CASE(40, a3, 0x280e09b0, li a0, 0x9abcdef1; mul a2, a0, a0; mulh a3, a0, a0)
  TEST_CASE(41, a2, 0x281edee1, nop)
  // A chain of four on the same sources, then one whose source changed in between.
  TEST_CASE(42, a5, 0x91999066, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulh a2, a0, a1; mul a3, a0, a1; mul a4, a0, a1; mulhu a5, a0, a1)
  TEST_CASE(43, a2, 0x05fadeb2, nop)
  TEST_CASE(44, a4, 0xae908393, nop)
  TEST_CASE(45, a3, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; addi a0, a0, 1; mulh a3, a0, a1)
  // A taken jump between the two.
  TEST_CASE(46, a3, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; j 1f; li a0, 0; 1: mulh a3, a0, a1)
  // A load result as a source, used by the first at once (load-use wait before it).
  TEST_CASE(47, a3, 0xfffffeec, lw a0, 0(s0); li a1, 0xf0e1d2c3; mul a2, a0, a1; mulh a3, a0, a1)
  // A divide between two multiplies, and a multiply right after a divide of the same sources.
  TEST_CASE(48, a4, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; div a3, a0, a1; mulh a4, a0, a1)
  // A MUL fused behind MULHSU or MULHU leaves that product in the unit, whose high half is not
  // MULH's: a MULH after it multiplies again (found by the differential test against QEMU).
  TEST_CASE(49, a4, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhsu a2, a0, a1; mul a3, a0, a1; mulh a4, a0, a1)
  TEST_CASE(50, a3, 0xae908393, nop)
  TEST_CASE(51, a4, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhu a2, a0, a1; mul a3, a0, a1; mulh a4, a0, a1)
  TEST_CASE(52, a4, 0xa0b7bda3, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mulhu a2, a0, a1; mul a3, a0, a1; mulhsu a4, a0, a1)
  // MUL, MUL (fused), MULH: the product in the unit is signed x signed either way.
  TEST_CASE(53, a4, 0x05fadeb2, li a0, 0x9abcdef1; li a1, 0xf0e1d2c3; mul a2, a0, a1; mul a3, a0, a1; mulh a4, a0, a1)
TEST_END
  .data
  .balign 4
mdata:
  .word 0x1234
