/* For board_icebreaker_test: on a SoC built without its GPU, a load from the RASTER registers, a
 * store into the framebuffer window and a load from the texture window each end in an access fault.
 * The trap handler sends mcause as a digit on the UART ('5' load, '7' store) and resumes after the
 * faulting instruction; then "E\n" and a loop. Bare: no crt0, linked at 0 without relaxation. */
    .section .text.init, "ax"
    .globl _start
_start:
    la      t0, trap
    csrw    mtvec, t0
    li      s0, 0x20001000      /* UART.DATA: a write waits while the TX FIFO is full */
    li      t1, 0x20003000      /* RASTER registers */
    lw      t2, 0(t1)
    li      t1, 0x30000000      /* framebuffer window */
    sw      zero, 0(t1)
    li      t1, 0x40000000      /* texture memory window */
    lw      t2, 0(t1)
    li      t0, 'E'
    sw      t0, 0(s0)
    li      t0, '\n'
    sw      t0, 0(s0)
1:  j       1b

trap:
    csrr    t3, mcause
    addi    t3, t3, '0'
    sw      t3, 0(s0)
    csrr    t3, mepc
    addi    t3, t3, 4
    csrw    mepc, t3
    mret
