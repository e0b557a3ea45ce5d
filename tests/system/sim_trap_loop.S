/* For sim_cli_test: a program that traps in a loop. Its first word is an illegal instruction and
 * mtvec is 0 after reset, so the trap returns to it and no instruction ever retires. */
  .text
  .globl _start
_start:
  .word 0
