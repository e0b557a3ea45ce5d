// Pipeline hazards: back-to-back dependencies through every forwarding path (write-back stage,
// last register write, register file), load-use, loads feeding addresses, stores and branches,
// multiply/divide results used at once, CSR results used at once, and x0 never forwarded.
#include "htx_test.h"
TEST_BEGIN
  // Distance 1, 2, 3 and 4 between producer and consumer, both operands.
  TEST_CASE(1, a2, 0x20, li a0, 0x10; add a2, a0, a0)
  TEST_CASE(2, a2, 0x11, li a0, 0x10; addi a1, x0, 1; add a2, a0, a1)
  TEST_CASE(3, a2, 0x11, li a0, 0x10; addi a1, x0, 1; nop; add a2, a1, a0)
  TEST_CASE(4, a2, 0x11, li a0, 0x10; addi a1, x0, 1; nop; nop; add a2, a1, a0)
  TEST_CASE(5, a2, 0x11, li a0, 0x10; addi a1, x0, 1; nop; nop; nop; add a2, a1, a0)
  // A chain where each result feeds the next.
  TEST_CASE(6, a0, 256, li a0, 1; add a0, a0, a0; add a0, a0, a0; add a0, a0, a0; add a0, a0, a0;
            add a0, a0, a0; add a0, a0, a0; add a0, a0, a0; add a0, a0, a0)
  // The newest of several writes to the same register wins.
  TEST_CASE(7, a2, 3, li a0, 1; li a0, 2; li a0, 3; mv a2, a0)
  TEST_CASE(8, a2, 6, li a0, 1; li a0, 2; li a0, 3; nop; add a2, a0, a0)
  // Load-use at distance 1, 2, 3.
  la s0, hdata
  TEST_CASE(9, a2, 0x1235, lw a1, 0(s0); addi a2, a1, 1)
  TEST_CASE(10, a2, 0x1235, lw a1, 0(s0); nop; addi a2, a1, 1)
  TEST_CASE(11, a2, 0x1235, lw a1, 0(s0); nop; nop; addi a2, a1, 1)
  TEST_CASE(12, a2, 0x2468, lw a1, 0(s0); add a2, a1, a1)
  // Load feeding the address of the next load (pointer chase) and of a store.
  TEST_CASE(13, a2, 0x1234, lw a1, 4(s0); lw a2, 0(a1))
  TEST_CASE(14, a2, 0x77, lw a1, 4(s0); li a3, 0x77; sw a3, 8(a1); lw a2, 8(s0))
  // Load feeding store data.
  TEST_CASE(15, a2, 0x1234, lw a1, 0(s0); sw a1, 12(s0); lw a2, 12(s0))
  // Load feeding a branch and a jump.
  TEST_CASE(16, a3, 1, li a3, 0; lw a1, 0(s0); bnez a1, 1f; li a3, 5; 1: addi a3, a3, 1)
  TEST_CASE(17, a3, 2, li a3, 0; la a1, 1f; sw a1, 16(s0); lw a2, 16(s0); jalr x0, 0(a2); li a3, 5;
            1: addi a3, a3, 2)
  // Load into x0 never forwards.
  TEST_CASE(18, a2, 0, lw x0, 0(s0); mv a2, x0)
  TEST_CASE(19, a2, 5, li a1, 5; lw x0, 0(s0); add a2, a1, x0)
  // Multiply and divide results used at once and as operands of each other.
  TEST_CASE(20, a2, 43, li a0, 6; li a1, 7; mul a2, a0, a1; addi a2, a2, 1)
  TEST_CASE(21, a2, 6, li a0, 6; li a1, 7; mul a2, a0, a1; div a2, a2, a1)
  TEST_CASE(22, a2, 0, li a0, 100; li a1, 7; rem a2, a0, a1; mul a2, a2, x0)
  TEST_CASE(23, a2, 2, li a0, 100; li a1, 7; divu a2, a0, a1; addi a2, a2, 2; remu a2, a2, a1; mulhu a3, a2, a2)
  // A multiply whose source E would forward waits a cycle (its signs set the correction terms):
  // negative sources straight from the instruction before, for each signedness.
  TEST_CASE(30, a2, 35, li a0, -5; li a1, 7; sub a1, x0, a1; mul a2, a0, a1)
  TEST_CASE(31, a2, 0xffffffff, li a1, 7; li a0, 5; sub a0, x0, a0; mulh a2, a0, a1)
  TEST_CASE(32, a2, 0, li a0, -5; li a1, 7; sub a1, x0, a1; mulh a2, a0, a1)
  TEST_CASE(33, a2, 0xffffffff, li a1, 7; li a0, 5; sub a0, x0, a0; mulhsu a2, a0, a1)
  TEST_CASE(34, a2, 4, li a0, 5; li a1, 7; sub a1, x0, a1; mulhu a2, a0, a1)
  TEST_CASE(35, a2, 4, li a0, 5; li a1, 7; sub a1, x0, a1; mulhsu a2, a0, a1)
  TEST_CASE(24, a2, 0x10, lw a1, 0(s0); li a0, 0x1234; divu a2, a1, a0; slli a2, a2, 4)
  // CSR read used at once; CSR write from a just-computed value.
  TEST_CASE(25, a2, 0x56, li a0, 0x55; addi a0, a0, 1; csrw mscratch, a0; csrr a1, mscratch; mv a2, a1)
  TEST_CASE(26, a2, 0x1234, lw a1, 0(s0); csrw mscratch, a1; csrr a2, mscratch)
  // Store then load of the same address back to back, and load after a store of another lane.
  TEST_CASE(27, a2, 0x12ab, li a1, 0xab; sb a1, 0(s0); lw a2, 0(s0); li a1, 0x34; sb a1, 0(s0))
  // A long load-use chain.
  TEST_CASE(28, a2, 0x1234, lw a1, 4(s0); lw a1, 20(a1); lw a1, 4(a1); lw a2, 0(a1))
  // Producer in write-back while a multi-cycle divide waits in execute.
  TEST_CASE(29, a2, 10, li a0, 50; li a1, 5; addi a3, x0, 9; divu a2, a0, a1)
TEST_END
  .data
  .balign 4
hdata:
  .word 0x1234        // 0
  .word hdata         // 4
  .word 0             // 8
  .word 0             // 12
  .word 0             // 16
  .word hdata         // 20
