// JAL and JALR: link values, JALR clears bit 0 of the target, rd = rs1, rd = x0, call/return,
// and no effect from the instructions after a jump.
#include "htx_test.h"
TEST_BEGIN
  // JAL links pc + 4 and skips what follows.
  TEST_CASE(1, a2, 0, li a3, 0; 1: jal a0, 2f; li a3, 1; li a3, 2; 2: la a1, 1b; addi a1, a1, 4;
            sub a2, a0, a1; add a2, a2, a3)
  // JAL with rd = x0 writes nothing.
  TEST_CASE(2, a3, 5, li a3, 5; jal x0, 1f; li a3, 6; 1: mv a4, x0; add a3, a3, a4)
  // JALR with an offset, link in ra.
  TEST_CASE(3, a3, 7, la a0, 2f; addi a0, a0, 8; li a3, 0; jalr ra, -8(a0); li a3, 99;
            2: li a3, 7)
  // JALR clears bit 0: target label + 1 lands on the label.
  TEST_CASE(4, a3, 11, la a0, 1f; addi a0, a0, 1; li a3, 0; jalr x0, 0(a0); li a3, 98;
            1: addi a3, a3, 11)
  // JALR with an odd offset: bit 0 of (rs1 + imm) is cleared, not of rs1.
  TEST_CASE(5, a3, 12, la a0, 1f; addi a0, a0, -1; li a3, 0; jalr x0, 1(a0); li a3, 97;
            1: addi a3, a3, 12)
  // JALR with rd = rs1: the target uses the old rs1, rd gets the link.
  TEST_CASE(6, a2, 0, la a0, 1f; 2: jalr a0, 0(a0); li a2, 1; 1: la a1, 2b; addi a1, a1, 4;
            sub a2, a0, a1)
  // Call and return through a small function; return address in ra.
  TEST_CASE(7, a0, 42, li a0, 40; call func_add2; j 1f; func_add2: addi a0, a0, 2; ret; 1:)
  // Nested calls (ra saved on the stack).
  TEST_CASE(8, a0, 13, li a0, 10; call func_outer; j 1f;
            func_outer: addi sp, sp, -16; sw ra, 12(sp); call func_add1; call func_add2b;
            lw ra, 12(sp); addi sp, sp, 16; ret;
            func_add1: addi a0, a0, 1; ret;
            func_add2b: addi a0, a0, 2; ret; 1:)
  // JALR to a target computed by the previous instruction (forwarding into the jump).
  TEST_CASE(9, a3, 3, la a0, 1f; li a3, 94; addi a0, a0, 8; jalr x0, 0(a0); li a3, 96;
            1: li a3, 95; li a3, 93; addi a3, a3, -91)
  // A backward JAL (predicted in decode).
  TEST_CASE(10, a3, 2, li a3, 0; j 2f; 1: addi a3, a3, 1; j 3f; 2: addi a3, a3, 1; j 1b; li a3, 50; 3:)
TEST_END
