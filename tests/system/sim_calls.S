/* For sim_cli_test's --hotspots check of calls: _start calls `outer` 50 times; `outer` calls
 * `leaf` twice, through a JAL and through a JALR, and `leaf` loops. Every clock of `outer` and
 * `leaf` lies between a call and its return, so each one's inclusive clocks are exact: `leaf`'s
 * its own, `outer`'s its own and `leaf`'s. A jump into `tail` (no link) is not a call: `tail`'s
 * clocks count in `outer`'s inclusive ones and it has no calls. Ends through tohost with status
 * 0. Bare, like sim_profile.S. */
    .section .text.init, "ax"
    .globl _start
_start:
    li      s0, 50
1:
    jal     ra, outer
    addi    s0, s0, -1
    bnez    s0, 1b
    la      t0, tohost
    li      t1, 1            /* (0 << 1) | 1: status 0 */
    sw      t1, 0(t0)
2:  j       2b

    .type   outer, @function
outer:
    mv      s1, ra
    jal     ra, leaf         /* a call through JAL */
    la      t2, leaf
    jalr    ra, 0(t2)        /* a call through JALR */
    mv      ra, s1
    j       tail             /* a jump, not a call: tail returns to outer's caller */
    .size   outer, . - outer

    .type   leaf, @function
leaf:
    li      t0, 5
3:  addi    t0, t0, -1
    bnez    t0, 3b
    ret
    .size   leaf, . - leaf

    .type   tail, @function
tail:
    addi    t3, t3, 1
    ret
    .size   tail, . - tail

    .data
    .balign 64
    .globl tohost
tohost:
    .word 0
