// BEQ BNE BLT BGE BLTU BGEU, taken and not taken, forward (predicted not taken) and backward
// (predicted taken) so both prediction outcomes and both mispredictions run; the instructions on
// the wrong path must have no effect.
#include "htx_test.h"

// a3 = 1 if the forward branch is taken, else 0.
#define TEST_BR_FWD(num, inst, taken, a, b)                              \
  TEST_CASE(num, a3, taken, li a0, a; li a1, b; li a3, 0;                \
            inst a0, a1, 1f; j 2f; li a3, 55; 1: li a3, 1; 2:)
// Same with a backward branch.
#define TEST_BR_BWD(num, inst, taken, a, b)                              \
  TEST_CASE(num, a3, taken, li a0, a; li a1, b; li a3, 0; j 3f;          \
            1: li a3, 1; j 2f; li a3, 66;                                \
            3: inst a0, a1, 1b; li a4, 0; 2:)

TEST_BEGIN
  TEST_BR_FWD(1, beq, 1, 5, 5)
  TEST_BR_FWD(2, beq, 0, 5, 6)
  TEST_BR_BWD(3, beq, 1, -1, -1)
  TEST_BR_BWD(4, beq, 0, 0, 1)
  TEST_BR_FWD(5, bne, 0, 5, 5)
  TEST_BR_FWD(6, bne, 1, 5, 6)
  TEST_BR_BWD(7, bne, 0, 7, 7)
  TEST_BR_BWD(8, bne, 1, 0x80000000, 0)
  TEST_BR_FWD(9, blt, 1, -1, 0)
  TEST_BR_FWD(10, blt, 0, 0, -1)
  TEST_BR_FWD(11, blt, 0, 3, 3)
  TEST_BR_BWD(12, blt, 1, 0x80000000, 0x7fffffff)
  TEST_BR_BWD(13, blt, 0, 0x7fffffff, 0x80000000)
  TEST_BR_FWD(14, bge, 1, 0, -1)
  TEST_BR_FWD(15, bge, 1, 3, 3)
  TEST_BR_FWD(16, bge, 0, -1, 0)
  TEST_BR_BWD(17, bge, 1, 0x7fffffff, 0x80000000)
  TEST_BR_BWD(18, bge, 0, 0x80000000, 0x7fffffff)
  TEST_BR_FWD(19, bltu, 0, -1, 0)
  TEST_BR_FWD(20, bltu, 1, 0, -1)
  TEST_BR_FWD(21, bltu, 0, 3, 3)
  TEST_BR_BWD(22, bltu, 0, 0x80000000, 0x7fffffff)
  TEST_BR_BWD(23, bltu, 1, 0x7fffffff, 0x80000000)
  TEST_BR_FWD(24, bgeu, 1, -1, 0)
  TEST_BR_FWD(25, bgeu, 0, 0, -1)
  TEST_BR_FWD(26, bgeu, 1, 3, 3)
  TEST_BR_BWD(27, bgeu, 1, 0x80000000, 0x7fffffff)
  TEST_BR_BWD(28, bgeu, 0, 0x7fffffff, 0x80000000)
  // A counted loop: backward branch taken 99 times, then not taken once.
  TEST_CASE(29, a2, 100, li a0, 100; li a2, 0; 1: addi a2, a2, 1; addi a0, a0, -1; bnez a0, 1b)
  // Nested loops with short bodies, branches back to back.
  TEST_CASE(30, a2, 60, li a0, 5; li a2, 0;
            1: li a1, 12; 2: addi a2, a2, 1; addi a1, a1, -1; bnez a1, 2b; addi a0, a0, -1; bnez a0, 1b)
  // Branch on the result of the instruction right before it (forwarding into the compare).
  TEST_CASE(31, a3, 1, li a0, 4; li a3, 0; addi a0, a0, -4; beqz a0, 1f; li a3, 9; 1: addi a3, a3, 1)
  // Two taken branches in a row.
  TEST_CASE(32, a3, 3, li a3, 0; beq x0, x0, 1f; li a3, 70; 1: addi a3, a3, 1;
            bne a3, x0, 2f; li a3, 80; 2: addi a3, a3, 2)
TEST_END
