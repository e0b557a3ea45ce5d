// Zicsr instructions CSRRW CSRRS CSRRC CSRRWI CSRRSI CSRRCI on mscratch, the WARL masks of mtvec and
// mepc, mstatus MIE/MPIE, misa and the id registers; illegal accesses (unknown CSR, writes to the
// read-only counter aliases and id registers) trap with cause 2 and mtval = 0.
#include "htx_test.h"

// Run `code` at label 8, which must trap as an illegal instruction (mepc = label 8, mtval = 0).
#define TEST_ILLEGAL(num, code...)                                       \
  TEST_CASE(num, s2, 2, la s7, 9f; li s2, 0; 8: code; j fail; 9:)        \
  la t0, 8b; bne s4, x0, fail; bne s3, t0, fail;

TEST_BEGIN
  la t0, csr_trap; csrw mtvec, t0
  TEST_CASE(1, a0, 0x12345678, li a1, 0x12345678; csrw mscratch, a1; csrr a0, mscratch)
  TEST_CASE(2, a0, 0x12345678, li a1, 0xcafe; csrrw a0, mscratch, a1)
  TEST_CASE(3, a0, 0x0000cafe, csrr a0, mscratch)
  TEST_CASE(4, a0, 0x0000cafe, li a1, 0xf0000001; csrrs a0, mscratch, a1)
  TEST_CASE(5, a0, 0xf000caff, csrr a0, mscratch)
  TEST_CASE(6, a0, 0xf000caff, li a1, 0x0000ffff; csrrc a0, mscratch, a1)
  TEST_CASE(7, a0, 0xf0000000, csrr a0, mscratch)
  TEST_CASE(8, a0, 0xf0000000, csrrwi a0, mscratch, 0x15)
  TEST_CASE(9, a0, 0x00000015, csrrsi a0, mscratch, 0x0a)
  TEST_CASE(10, a0, 0x0000001f, csrrci a0, mscratch, 0x11)
  TEST_CASE(11, a0, 0x0000000e, csrr a0, mscratch)
  // csrrs/csrrc with x0 or uimm 0 read without writing.
  TEST_CASE(12, a0, 0x0000000e, csrrs a0, mscratch, x0; csrrc a0, mscratch, x0; csrrsi a0, mscratch, 0)
  // rd = x0: a pure write.
  TEST_CASE(13, a0, 0x00000077, li a1, 0x77; csrrw x0, mscratch, a1; csrr a0, mscratch)
  // Back-to-back: write then read then use.
  TEST_CASE(14, a0, 0x00000079, li a1, 0x78; csrw mscratch, a1; csrr a0, mscratch; addi a0, a0, 1)
  // mtvec is direct mode only: the low two bits read 0.
  TEST_CASE(15, a0, 0x00001230, li a1, 0x00001233; csrrw a2, mtvec, a1; csrr a0, mtvec; csrw mtvec, a2)
  // mepc holds 4-aligned addresses.
  TEST_CASE(16, a0, 0x00004440, li a1, 0x00004443; csrw mepc, a1; csrr a0, mepc)
  // mstatus: MIE (bit 3) and MPIE (bit 7) are writable, MPP reads machine mode (3).
  TEST_CASE(17, a0, 0x00001888, li a1, 0x88; csrw mstatus, a1; csrr a0, mstatus)
  TEST_CASE(18, a0, 0x00001800, li a1, 0xffffffff; csrc mstatus, a1; csrr a0, mstatus)
  TEST_CASE(19, a0, 0x40001100, csrr a0, misa)
  TEST_CASE(20, a0, 0, csrr a0, mhartid; csrr a1, mvendorid; or a0, a0, a1; csrr a1, marchid;
            or a0, a0, a1; csrr a1, mimpid; or a0, a0, a1)
  TEST_CASE(21, a0, 0, csrr a0, mie; csrr a1, mip; or a0, a0, a1)
  // Reading the read-only aliases with csrrs/csrrc x0 is legal.
  TEST_CASE(22, a0, 0, csrrs a1, cycle, x0; csrrc a1, instret, x0; csrrsi a1, cycleh, 0; li a0, 0)
  TEST_ILLEGAL(23, csrw cycle, a0)
  TEST_ILLEGAL(24, csrrs a1, instret, a0)
  TEST_ILLEGAL(25, csrrci a1, cycleh, 1)
  TEST_ILLEGAL(26, csrrwi x0, instreth, 0)
  TEST_ILLEGAL(27, csrw mhartid, a0)
  TEST_ILLEGAL(28, csrr a0, 0x7c0)
  TEST_ILLEGAL(29, csrr a0, time)
  TEST_ILLEGAL(30, csrr a0, 0x3a0)
  // A trapping CSR instruction does not write its rd.
  TEST_CASE(31, a1, 0x55, li a1, 0x55; la s7, 1f; csrrw a1, 0x7c0, a0; 1:)
  // The privileged spec's zero CSRs: mconfigptr (read-only), mstatush (little-endian only),
  // mhpmcounter3-31(h) and mhpmevent3-31 (hardwired to zero, writes ignored).
  TEST_CASE(32, a0, 0, li a0, -1; csrr a0, 0xf15)
  TEST_ILLEGAL(33, csrw 0xf15, a0)
  TEST_CASE(34, a0, 0, li a1, -1; csrw 0x310, a1; csrr a0, 0x310)
  TEST_CASE(35, a0, 0, li a1, -1; csrw 0xb03, a1; csrr a0, 0xb03; csrw 0xb1f, a1; csrr a2, 0xb1f;
            or a0, a0, a2)
  TEST_CASE(36, a0, 0, li a1, -1; csrw 0xb83, a1; csrr a0, 0xb83; csrs 0xb9f, a1; csrr a2, 0xb9f;
            or a0, a0, a2)
  TEST_CASE(37, a0, 0, li a1, -1; csrw 0x323, a1; csrr a0, 0x323; csrw 0x33f, a1; csrr a2, 0x33f;
            or a0, a0, a2)
  // Their neighbours are not CSRs here: 0xB01 and 0xB81 (no machine time), mcountinhibit (0x320,
  // optional), 0x321, 0x322, the user hpmcounter3 alias (no Zihpm).
  TEST_ILLEGAL(38, csrr a0, 0xb01)
  TEST_ILLEGAL(39, csrr a0, 0xb81)
  TEST_ILLEGAL(40, csrr a0, 0x320)
  TEST_ILLEGAL(41, csrr a0, 0x322)
  TEST_ILLEGAL(42, csrr a0, 0xc03)
  TEST_ILLEGAL(43, csrr a0, 0xb20)
TEST_END
  .text
TRAP_HANDLER(csr_trap)
