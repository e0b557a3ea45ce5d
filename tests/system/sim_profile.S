/* For sim_cli_test's cycle-profile check: a loop whose every iteration costs the pipeline a known
 * set of clocks (docs/cpu.md, "Hazards and forwarding"), built with two loop counts so the test can
 * compare the profiles' differences exactly. Ends through tohost with status 0. Bare, like
 * sim_signature.S. */
#ifndef LOOPS
#error "build with -DLOOPS=<iterations>"
#endif
    .section .text.init, "ax"
    .globl _start
_start:
    la      a0, data_word
    li      t0, LOOPS
1:
    lw      t1, 0(a0)        /* a load whose data ... */
    add     t2, t1, t1       /* ... the next instruction uses: one load_use clock */
    slli    t3, t2, 1        /* a shift whose result ... */
    add     t4, t3, t3       /* ... the next instruction uses: one late_result clock */
    srai    t6, t4, 2        /* and again: */
    xor     t4, t6, t4       /*   a second late_result clock; and a multiply that uses ... */
    mul     t5, t4, t4       /* ... it waits too (a third); three clocks in execute: two mul_div clocks */
    addi    t0, t0, -1
    bnez    t0, 1b           /* backward, predicted taken: one jump clock (mispredicted once, at the end) */
    la      t0, tohost
    li      t1, 1            /* (0 << 1) | 1: status 0 */
    sw      t1, 0(t0)
2:  j       2b

    .data
    .balign 4
data_word:
    .word 3
    .balign 64
    .globl tohost
tohost:
    .word 0
