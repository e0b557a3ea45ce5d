/* Reset entry for hypertex firmware: trap vector, global pointer, stack, .data and .tdata copied
 * from their load image (linker/hypertex.ld), .bss and .tbss clear, thread pointer for picolibc's TLS, the target
 * set-up (UART divisor), C++ constructors (init_array), main, then exit with main's status. */
    .section .text.init, "ax"
    .globl _start
_start:
    /* Traps before main (or unexpected ones later) are reported, not silently looped on. */
    la      t0, htx_trap_entry
    csrw    mtvec, t0
    .option push
    .option norelax
    la      gp, __global_pointer$
    .option pop
    la      sp, __stack_top

    /* .data and .tdata (adjacent) from their load image, at every start: a warm reset (a board's
       reset button) must not run with the values the last run left. */
    la      a0, __data_start
    la      a1, __data_image
    la      a2, __data_copy_end
1:  bgeu    a0, a2, 2f
    lw      t0, 0(a1)
    sw      t0, 0(a0)
    addi    a0, a0, 4
    addi    a1, a1, 4
    j       1b
2:
    /* .bss (and .tbss, which the linker script places at its start) */
    la      a0, __bss_start
    la      a1, __bss_end
3:  bgeu    a0, a1, 4f
    sw      zero, 0(a0)
    addi    a0, a0, 4
    j       3b
4:
    la      tp, __tls_base

    call    htx_target_init
    call    __libc_init_array     /* preinit_array, init_array: C++ constructors */
    li      a0, 0
    li      a1, 0
    call    main
    call    exit                  /* runs destructors/atexit, then _exit */
5:  j       5b
