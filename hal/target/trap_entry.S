/* Default machine trap vector: the firmware has no interrupts, so any trap is a bug (illegal
 * instruction, misaligned or faulting access, ecall/ebreak without a handler). Saves nothing: the
 * C reporter never returns. A fresh stack at the top of RAM keeps a corrupted sp from hiding it. */
    .section .text.htx_trap, "ax"
    .balign 4
    .globl htx_trap_entry
htx_trap_entry:
    la      sp, __stack_top
    csrr    a0, mcause
    csrr    a1, mepc
    csrr    a2, mtval
    call    htx_trap_report
1:  j       1b
