/* For sim_cli_test: computes four words into the signature area, then ends through tohost with
 * status 3 ((3 << 1) | 1). Bare: no crt0 and no gp, so it is linked without relaxation.
 * Variants for the harness's refusals and statuses (tests/system/CMakeLists.txt): TOHOST_WORD, the
 * word it ends with; PUTCHAR_FIRST, a character without a newline on SIM_PUTCHAR before that;
 * SIGNATURE_SKEW, bytes before begin_signature; TOHOST_INITIAL, tohost's value in the image. */
#ifndef TOHOST_WORD
#define TOHOST_WORD 7
#endif
#ifndef SIGNATURE_SKEW
#define SIGNATURE_SKEW 0
#endif
#ifndef TOHOST_INITIAL
#define TOHOST_INITIAL 0
#endif
    .section .text.init, "ax"
    .globl _start
_start:
    la      t0, begin_signature
    li      t1, 0xdeadbeef
    sw      t1, 0(t0)
    /* word 1 stays 0 (from the image) */
    lui     t1, 0x12345
    addi    t1, t1, 0x678
    sw      t1, 8(t0)
    li      t1, -7
    sw      t1, 12(t0)
#ifdef PUTCHAR_FIRST
    li      t0, 0x20000018      /* SYSCTRL SIM_PUTCHAR */
    li      t1, 'A'
    sw      t1, 0(t0)
#endif
    la      t0, tohost
    li      t1, TOHOST_WORD
    sw      t1, 0(t0)
1:  j       1b

    .data
    .balign 16
    .skip   SIGNATURE_SKEW
    .globl begin_signature
begin_signature:
    .word 0x11111111, 0, 0x22222222, 0x33333333
    .globl end_signature
end_signature:
    .balign 64
    .globl tohost
tohost:
    .word TOHOST_INITIAL
