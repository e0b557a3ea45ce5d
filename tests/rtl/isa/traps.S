// Every trap cause with mcause, mepc and mtval checked, and MRET: ECALL (11), EBREAK (3), illegal
// instruction (2, mtval = 0: a handler finds the instruction at mepc), instruction address
// misaligned on JAL/JALR/taken branch (0, mtval = target; not-taken branches do not trap),
// load/store address misaligned (4/6, mtval = address), load/store access fault (5/7, mtval =
// address) and instruction access fault (1).
// A trapping instruction has no other effect.
#include "htx_test.h"

#define UNMAPPED 0x10000000

// Runs `code` at label 8 and expects a trap with the given cause, mepc at label 8 and mtval.
#define TEST_TRAP(num, cause, tval, code...)                             \
  li TESTNUM, num;                                                       \
  la s7, 9f; li s2, 0x7f; li s3, 0; li s4, 0x7f;                         \
  8: code;                                                               \
  j fail;                                                                \
  9: li t6, cause; bne s2, t6, fail;                                     \
  la t6, 8b; bne s3, t6, fail;                                           \
  la t6, tval; bne s4, t6, fail;

TEST_BEGIN
  j 1f
  .half 0
misaligned_back:          // 2 mod 4: a target for backward branches and jumps
  .half 0
1:
  la t0, trap_handler; csrw mtvec, t0
  TEST_TRAP(1, 11, 0, ecall)
  TEST_TRAP(2, 3, 0, ebreak)
  TEST_TRAP(3, 2, 0, .word 0x00000000)
  TEST_TRAP(4, 2, 0, .word 0xffffffff)
  TEST_TRAP(5, 2, 0, .word 0x40001033)   // SLL with funct7 0100000
  TEST_TRAP(6, 2, 0, .word 0x02001013)   // SLLI with shamt[5] set (RV64 only)
  TEST_TRAP(7, 2, 0, .word 0x0000b003)   // LD (RV64 only)
  TEST_TRAP(8, 2, 0, .word 0x00003023)   // SD (RV64 only)
  TEST_TRAP(9, 2, 0, .word 0x00002063)   // branch funct3 010
  TEST_TRAP(10, 2, 0, .word 0x00001067)  // JALR funct3 001
  TEST_TRAP(11, 2, 0, .word 0x10200073)  // SRET: no supervisor mode
  TEST_TRAP(12, 2, 0, .word 0x00004073)  // SYSTEM funct3 100
  TEST_TRAP(13, 2, 0, .word 0x00000007)  // FLW opcode: no F extension
  TEST_TRAP(14, 2, 0, .word 0x00000001)  // compressed encoding: no C extension
  TEST_TRAP(15, 2, 0, .word 0x0200402b)  // custom-1 opcode
  // Misaligned loads and stores; byte accesses never trap.
  la a0, tdata
  TEST_TRAP(16, 4, tdata + 1, lw a1, 1(a0))
  TEST_TRAP(17, 4, tdata + 2, lw a1, 2(a0))
  TEST_TRAP(18, 4, tdata + 3, lw a1, 3(a0))
  TEST_TRAP(19, 4, tdata + 1, lh a1, 1(a0))
  TEST_TRAP(20, 4, tdata + 3, lhu a1, 3(a0))
  TEST_TRAP(21, 6, tdata + 1, sw a1, 1(a0))
  TEST_TRAP(22, 6, tdata + 2, sw a1, 2(a0))
  TEST_TRAP(23, 6, tdata + 3, sh a1, 3(a0))
  // A misaligned load leaves rd alone; a misaligned store leaves memory alone.
  TEST_CASE(24, a1, 0x33, li a1, 0x33; la s7, 1f; lw a1, 1(a0); 1:)
  TEST_CASE(25, a2, 0x11223344, li a1, 0x11223344; sw a1, 0(a0); la s7, 1f; li a3, -1; sh a3, 1(a0);
            1: lw a2, 0(a0))
  // Misaligned jump targets: the jump traps (mepc = the jump), mtval = the target, rd unchanged.
  TEST_TRAP(26, 0, misaligned_target, jal a5, misaligned_target)
  TEST_CASE(27, a5, 0x5a, li a5, 0x5a; la s7, 1f; jal a5, misaligned_target; 1:)
  la a1, aligned_target
  TEST_TRAP(28, 0, aligned_target + 2, jalr a5, 2(a1))
  TEST_TRAP(29, 0, aligned_target + 2, jalr a5, 3(a1))
  TEST_CASE(30, a5, 0x5b, li a5, 0x5b; la s7, 1f; jalr a5, 2(a1); 1:)
  TEST_TRAP(31, 0, misaligned_target, beq x0, x0, misaligned_target)
  TEST_TRAP(32, 0, misaligned_target, bne a1, x0, misaligned_target)
  // A not-taken branch to a misaligned target is fine.
  TEST_CASE(33, a3, 4, li a3, 4; bne x0, x0, misaligned_target; blt a1, x0, misaligned_target)
  // Backward branch and JAL to a misaligned target (decode predicts those taken).
  TEST_TRAP(34, 0, misaligned_back, beq x0, x0, misaligned_back)
  TEST_TRAP(35, 0, misaligned_back, jal x0, misaligned_back)
  // Access faults from the bus, for loads and stores; rd unchanged.
  li a0, UNMAPPED
  TEST_TRAP(36, 5, UNMAPPED + 4, lw a1, 4(a0))
  TEST_TRAP(37, 5, UNMAPPED + 1, lbu a1, 1(a0))
  TEST_TRAP(38, 7, UNMAPPED + 8, sw a1, 8(a0))
  TEST_TRAP(39, 7, UNMAPPED + 2, sh a1, 2(a0))
  TEST_CASE(40, a1, 0x66, li a1, 0x66; la s7, 1f; lw a1, 0(a0); 1:)
  // The instructions after a faulting load have no effect.
  TEST_CASE(41, a3, 7, li a3, 7; la s7, 1f; lw a1, 0(a0); li a3, 8; li a3, 9; 1:)
  // Instruction access fault: jump to an unmapped address; mepc = mtval = that address.
  li TESTNUM, 42
  la s7, 1f
  li a0, UNMAPPED + 0x40
  jalr x0, 0(a0)
  j fail
1:
  li t6, 1; bne s2, t6, fail
  li t6, UNMAPPED + 0x40; bne s3, t6, fail; bne s4, t6, fail
  // MRET: the trap saves MIE in MPIE and clears MIE; MRET restores MIE from MPIE and sets MPIE.
  TEST_CASE(43, s6, 0x00001880, li a1, 0x8; csrw mstatus, a1; la s7, 1f; ecall; 1:)   // in the handler
  TEST_CASE(44, a0, 0x00001888, csrr a0, mstatus)   // after the handler's MRET
  // MRET with MIE=1, MPIE=0: MIE takes MPIE (0), MPIE becomes 1.
  TEST_CASE(45, a0, 0x00001880, la a1, 1f; csrw mepc, a1; li a1, 0x8;
            csrw mstatus, a1; mret; j fail; 1: csrr a0, mstatus)
  // ECALL and faulting instructions are not counted in instret: between the reads retire
  // rdinstret, la (2) and the handler's 6 instructions, but not the ecall or the faulting load.
  TEST_CASE(46, a2, 9, rdinstret a0; la s7, 1f; ecall; 1: rdinstret a1; sub a2, a1, a0)
  TEST_CASE(47, a2, 9, li a3, UNMAPPED; rdinstret a0; la s7, 1f; lw a4, 0(a3); 1: rdinstret a1;
            sub a2, a1, a0)
  // Traps back to back: the handler itself runs normally between them.
  TEST_TRAP(48, 11, 0, ecall)
  TEST_TRAP(49, 3, 0, ebreak)
  // The instruction right behind a trapping one has no effect either: not a store, a CSR write,
  // MRET or a divide, whether the trap was found before execute (ECALL, illegal, a misaligned
  // load) or in it (a taken branch to a misaligned target).
  la a0, tdata
  TEST_CASE(50, a2, 0x5555, li a1, 0x5555; sw a1, 0(a0); li a3, 0x7777; la s7, 1f; ecall;
            sw a3, 0(a0); 1: lw a2, 0(a0))
  TEST_CASE(51, a2, 0x5555, li a3, 0x7777; la s7, 1f; .word 0; sh a3, 0(a0); 1: lw a2, 0(a0))
  TEST_CASE(52, a2, 0x5555, li a3, 0x7777; la s7, 1f; lw a1, 1(a0); sw a3, 0(a0); 1: lw a2, 0(a0))
  TEST_CASE(53, a2, 0x5555, li a3, 0x7777; la s7, 1f; beq x0, x0, misaligned_target; sw a3, 0(a0);
            1: lw a2, 0(a0))
  TEST_CASE(54, a2, 0x1234, li a1, 0x1234; csrw mscratch, a1; li a3, 0x4321; la s7, 1f; ebreak;
            csrw mscratch, a3; 1: csrr a2, mscratch)
  TEST_CASE(55, a2, 0x1234, li a3, 0x4321; la s7, 1f; .word 0xffffffff; csrw mscratch, a3;
            1: csrr a2, mscratch)
  TEST_CASE(56, a2, 0x1234, li a3, 0x4321; la s7, 1f; beq x0, x0, misaligned_target;
            csrw mscratch, a3; 1: csrr a2, mscratch)
  TEST_CASE(57, a4, 0x66, li a4, 0x66; li a1, 100; li a3, 7; la s7, 1f; ecall; div a4, a1, a3; 1:)
  // An MRET that acted would first set MIE from MPIE (0 here), and the handler would see MPIE 0.
  TEST_CASE(58, s6, 0x00001880, li a1, 0x8; csrw mstatus, a1; la s7, 1f; ecall; mret; 1:)
TEST_END
  .section .text.init, "ax"   // same section as the tests, so branches reach the targets directly
TRAP_HANDLER(trap_handler)
  .balign 4
aligned_target:
  .half 0
misaligned_target:        // 2 mod 4: a target for forward branches and jumps
  .half 0
  j fail

  .data
  .balign 4
tdata:
  .word 0, 0
