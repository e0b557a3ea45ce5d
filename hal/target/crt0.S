/* Reset entry for hypertex firmware: global pointer, stack, .data copy (when it has a separate load
 * address), .bss and .tbss clear, thread pointer for picolibc's TLS, constructors, main, exit. */
    .section .text.init, "ax"
    .globl _start
_start:
    .option push
    .option norelax
    la      gp, __global_pointer$
    .option pop
    la      sp, __stack_top

    /* .data: copy only if the loader left it elsewhere (a ROM image); in RAM images it is in place. */
    la      a0, __data_start
    la      a1, __data_source
    la      a2, __data_end
    beq     a0, a1, 2f
1:  bgeu    a0, a2, 2f
    lw      t0, 0(a1)
    sw      t0, 0(a0)
    addi    a0, a0, 4
    addi    a1, a1, 4
    j       1b
2:
    /* .bss */
    la      a0, __bss_start
    la      a1, __bss_end
3:  bgeu    a0, a1, 4f
    sw      zero, 0(a0)
    addi    a0, a0, 4
    j       3b
4:
    la      tp, __tls_base

    call    __libc_init_array
    li      a0, 0
    li      a1, 0
    call    main
    call    exit
5:  j       5b
