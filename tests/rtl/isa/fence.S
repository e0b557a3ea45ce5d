// FENCE is a no-op for this single in-order hart; FENCE.I makes instructions stored by the program
// visible to fetch (self-modifying code), including one already prefetched right behind it.
#include "htx_test.h"
TEST_BEGIN
  TEST_CASE(1, a0, 3, li a0, 1; fence; addi a0, a0, 1; fence rw, rw; addi a0, a0, 1)
  // Patch the subroutine's first instruction (addi a0, a0, 1) to addi a0, a0, 100 and call it.
  TEST_CASE(2, a0, 100, la a1, patch; li a2, 0x06450513; sw a2, 0(a1); fence.i; li a0, 0; call patch)
  // Patch it back.
  TEST_CASE(3, a0, 1, la a1, patch; li a2, 0x00150513; sw a2, 0(a1); fence.i; li a0, 0; call patch)
  // Patch the instruction right after the FENCE.I.
  TEST_CASE(4, a0, 100, la a1, 1f; li a2, 0x06450513; li a0, 0; sw a2, 0(a1); fence.i;
            1: addi a0, a0, 1)
TEST_END
  .section .text.init, "ax"
patch:
  addi a0, a0, 1
  ret
