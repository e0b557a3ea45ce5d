// Start-up for the CPI benchmark: stack, .bss clear, main(), then the exit conventions of the
// instruction tests (tohost 1 and SIM_EXIT 0 when main returns 0; otherwise the code (r << 1) | 1).
  .section .text.init, "ax"
  .globl _start
_start:
  la sp, __stack_top
  la t0, __bss_start
  la t1, __bss_end
1:
  bgeu t0, t1, 2f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 1b
2:
  call main
  li t0, 1
  beqz a0, 3f
  slli t0, a0, 1
  ori t0, t0, 1
  mv a0, t0
  j 4f
3:
  li a0, 0
4:
  la t1, tohost
  sw t0, 0(t1)
  li t1, 0x20000014          // SYSCTRL SIM_EXIT (hw/regs/sysctrl.json)
  sw a0, 0(t1)
5:
  j 5b

  .section .tohost, "aw", @progbits
  .balign 64
  .globl tohost
tohost: .word 0
  .balign 64
