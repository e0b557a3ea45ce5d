// cycle/instret counters: the user aliases (0xC00, 0xC02, 0xC80, 0xC82) read the machine counters,
// instret counts exactly the retired instructions, writes to mcycle/minstret(h) take effect for the
// next instruction, and a carry from the low half reaches the high half (read hi/lo/hi consistently).
#include "htx_test.h"
TEST_BEGIN
  // Three instructions between two reads: the second read sees 4 more.
  TEST_CASE(1, a2, 4, rdinstret a0; nop; addi a3, a3, 1; nop; rdinstret a1; sub a2, a1, a0)
  // Each read of instret right after another sees exactly one more.
  TEST_CASE(2, a2, 1, rdinstret a0; rdinstret a1; sub a2, a1, a0)
  // The user alias and the machine register agree (one instruction apart).
  TEST_CASE(3, a2, 1, csrr a0, minstret; rdinstret a1; sub a2, a1, a0)
  // cycle advances at least once per instruction and by exactly the clock count otherwise;
  // a run of 8 nops between reads takes at least 9 cycles.
  TEST_CASE(4, a3, 1, rdcycle a0; nop; nop; nop; nop; nop; nop; nop; nop; rdcycle a1; sub a2, a1, a0;
            sltiu a3, a2, 9; xori a3, a3, 1)
  TEST_CASE(5, a3, 1, csrr a0, mcycle; rdcycle a1; sltu a3, a0, a1)
  // Taken branches and a trap-free loop count one per executed instruction.
  TEST_CASE(6, a2, 32, rdinstret a0; li a4, 10; 1: addi a4, a4, -1; nop; bnez a4, 1b; rdinstret a1;
            sub a2, a1, a0)
  // Writing minstret: the next instruction reads the value written.
  TEST_CASE(7, a0, 0x00001000, li a1, 0x1000; csrw minstret, a1; csrr a0, minstret)
  TEST_CASE(8, a0, 0x00000077, li a1, 0x77; csrw minstreth, a1; csrr a0, minstreth)
  TEST_CASE(9, a0, 0x00000077, rdinstreth a0)
  // Writing mcycle: a read two instructions later sees the value plus the cycles in between.
  TEST_CASE(10, a3, 1, li a1, 0x5000; csrw mcycle, a1; nop; rdcycle a0; sub a2, a0, a1;
            sltiu a3, a2, 200; snez a4, a2; and a3, a3, a4)
  // Carry into cycleh: start just below 2^32, wait, then read hi, lo, hi until hi is stable.
  TEST_CASE(11, a0, 0x00000001, csrw mcycleh, x0; li a1, 0xfffffff0; csrw mcycle, a1;
            li a4, 20; 1: addi a4, a4, -1; bnez a4, 1b;
            2: rdcycleh a0; rdcycle a2; rdcycleh a3; bne a0, a3, 2b)
  TEST_CASE(12, a3, 1, sltiu a3, a2, 1000)
  TEST_CASE(13, a0, 0x00000001, csrr a0, mcycleh)
  // The machine high halves are writable as well.
  TEST_CASE(14, a0, 0x00000abc, li a1, 0xabc; csrw mcycleh, a1; csrr a0, mcycleh)
  // Carry into instreth.
  TEST_CASE(15, a0, 0x00000009, li a1, 8; csrw minstreth, a1; li a1, 0xfffffff8; csrw minstret, a1;
            nop; nop; nop; nop; nop; nop; nop; nop; nop; nop;
            2: rdinstreth a0; rdinstret a2; rdinstreth a3; bne a0, a3, 2b)
  TEST_CASE(16, a3, 1, sltiu a3, a2, 20)
  // Reading a counter in a back-to-back sequence of reads of different halves.
  TEST_CASE(17, a0, 0x00000009, csrr a0, minstreth)
TEST_END
