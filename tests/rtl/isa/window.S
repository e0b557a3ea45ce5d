// The executable window (docs/cpu.md, "Executable window"): with PcBits 18, as the test benches
// and the SoC for 128 KiB of RAM set it, instructions are fetched from [0, 0x3FFF8] only. A fetch
// at the window's last word or outside it is an instruction access fault (1) with mepc = mtval =
// the address, as a bus error on the fetch would be, after the jump, branch or MRET that led there
// has completed: its link is written and it counts in minstret. Backward branches and JAL are
// predicted taken, so the cases with those go through fetch's prediction first.
#include "htx_test.h"

#define WINDOW_LAST 0x0003FFFC

// Runs `code` at label 8, which must end in an instruction access fault at `addr`.
#define TEST_FETCH_FAULT(num, addr, code...)                             \
  li TESTNUM, num;                                                       \
  la s7, 9f; li s2, 0x7f; li s3, 0; li s4, 0x7f;                         \
  8: code;                                                               \
  j fail;                                                                \
  9: li t6, 1; bne s2, t6, fail;                                         \
  la t6, addr; bne s3, t6, fail; bne s4, t6, fail;

TEST_BEGIN
  la t0, trap_handler; csrw mtvec, t0
  // First, while the code is still below 4 KiB: backward to a negative address (a predicted-taken
  // branch and JAL whose targets wrap below 0).
  TEST_FETCH_FAULT(1, 8b - 4096, beq x0, x0, . - 4096)
  TEST_FETCH_FAULT(2, 8b - 0x80000, jal x0, . - 0x80000)
  // A backward branch predicted taken but not taken falls through, whatever its target.
  TEST_CASE(3, a2, 2, li a2, 1; bne x0, x0, . - 4096; li a2, 2)
  // JALR to the window's last word, just past it, and far outside.
  TEST_FETCH_FAULT(4, WINDOW_LAST, li a0, WINDOW_LAST; jalr x0, 0(a0))
  TEST_FETCH_FAULT(5, 0x00040000, li a0, 0x00040000; jalr x0, 0(a0))
  TEST_FETCH_FAULT(6, 0x80000000, li a0, 0x7ffffff0; jalr x0, 0x10(a0))
  // A JAL forward out of the window.
  TEST_FETCH_FAULT(7, 8b + 0x40000, jal x0, . + 0x40000)
  // MRET to an address outside: mepc keeps it.
  TEST_FETCH_FAULT(8, 0xfffffffc, li a1, 0xfffffffc; csrw mepc, a1; mret)
  // The jump completed: its link register holds the return address.
  TEST_FETCH_FAULT(9, 8b + 0x40000, jal ra, . + 0x40000)
  la t6, 8b + 4; bne ra, t6, fail
  TEST_FETCH_FAULT(10, 0x00123450, li a0, 0x00123450; jalr ra, 0(a0); 7:)
  la t6, 7b; bne ra, t6, fail
  // ... and retired: rdinstret, la (2), the JALR and the handler's 6 instructions.
  TEST_CASE(11, a2, 10, li a3, 0x00040000; rdinstret a0; la s7, 1f; jalr x0, 0(a3); 1: rdinstret a1;
            sub a2, a1, a0)
  // A redirect inside the window afterwards runs normally.
  TEST_CASE(12, a2, 5, li a2, 5; li a0, 0x00040000; la s7, 1f; jalr x0, 0(a0); 1:)
TEST_END
  .section .text.init, "ax"
TRAP_HANDLER(trap_handler)
