// Macros for the self-checking instruction tests (assembly, preprocessed by the C preprocessor).
//
// Register conventions: gp (x3) holds the number of the running test case, t6 (x31) the expected
// value; a test case must not use either as a result register. A failing check jumps to `fail`.
// The run ends with a store of the RISC-V test `tohost` code (1 = pass, testnum << 1 | 1 = fail;
// a failure before the first test case fails as test HTX_TEST_BEFORE_FIRST)
// followed by a write of the exit status to SYSCTRL SIM_EXIT (0 = pass, the tohost code = fail),
// so both the standalone CPU testbench and `htx sim` see the result. An unexpected trap fails.
#pragma once

#define TESTNUM gp

// The test number a failure before the first test case reports (an unexpected trap in the set-up):
// TESTNUM is 0 there, and (0 << 1) | 1 is tohost's pass code. 127 keeps the exit status one byte.
#define HTX_TEST_BEFORE_FIRST 127

// SYSCTRL simulation exit port (hw/regs/sysctrl.json: base 0x20000000, SIM_EXIT at 0x014).
#define HTX_SIM_EXIT_ADDR 0x20000014

#define TEST_BEGIN                                                       \
  .section .text.init, "ax";                                             \
  .globl _start;                                                         \
  _start:                                                                \
  la t0, htx_unexpected_trap;                                            \
  csrw mtvec, t0;                                                        \
  la sp, __stack_top;                                                    \
  li TESTNUM, 0;                                                         \
  j htx_tests;                                                           \
  .balign 4;                                                             \
  htx_unexpected_trap:                                                   \
  j fail;                                                                \
  htx_tests:

#define TEST_END                                                         \
  pass:                                                                  \
  li a0, 1;                                                              \
  la t0, tohost;                                                         \
  sw a0, 0(t0);                                                          \
  li t0, HTX_SIM_EXIT_ADDR;                                              \
  sw zero, 0(t0);                                                        \
  1: j 1b;                                                               \
  fail:                                                                  \
  bnez TESTNUM, 3f;                                                      \
  li TESTNUM, HTX_TEST_BEFORE_FIRST;                                     \
  3: slli a0, TESTNUM, 1;                                                \
  ori a0, a0, 1;                                                         \
  la t0, tohost;                                                         \
  sw a0, 0(t0);                                                          \
  li t0, HTX_SIM_EXIT_ADDR;                                              \
  sw a0, 0(t0);                                                          \
  2: j 2b;                                                               \
  .section .tohost, "aw", @progbits;                                     \
  .balign 64;                                                            \
  .globl tohost;                                                         \
  tohost: .word 0;                                                       \
  .balign 64;

// Runs `code`, then checks that `reg` holds `expected`.
#define TEST_CASE(num, reg, expected, code...)                           \
  li TESTNUM, num;                                                       \
  code;                                                                  \
  li t6, expected;                                                       \
  bne reg, t6, fail;

// reg-reg and reg-imm operations: d = op(a, b).
#define TEST_RR(num, inst, expected, a, b)                               \
  TEST_CASE(num, a2, expected, li a0, a; li a1, b; inst a2, a0, a1)
#define TEST_RI(num, inst, expected, a, imm)                             \
  TEST_CASE(num, a2, expected, li a0, a; inst a2, a0, imm)
// Destination equal to a source.
#define TEST_RR_SRC1_EQ_DEST(num, inst, expected, a, b)                  \
  TEST_CASE(num, a0, expected, li a0, a; li a1, b; inst a0, a0, a1)
#define TEST_RR_SRC2_EQ_DEST(num, inst, expected, a, b)                  \
  TEST_CASE(num, a1, expected, li a0, a; li a1, b; inst a1, a0, a1)

// A trap handler for tests that provoke traps: records mcause in s2, mepc in s3, mtval in s4 and
// mstatus in s6, then resumes at the address the test put in s7 beforehand.
#define TRAP_HANDLER(label)                                              \
  .balign 4;                                                             \
  label:                                                                 \
  csrr s2, mcause;                                                       \
  csrr s3, mepc;                                                         \
  csrr s4, mtval;                                                        \
  csrr s6, mstatus;                                                      \
  csrw mepc, s7;                                                         \
  mret;
