// Seeded random RV32IM programs for the differential test of htx_cpu against QEMU
// (cpu_qemu_diff_test.cpp, docs/cpu.md "Verification").
//
// A program loads x1..x30 from a table, runs a random body (every RV32IM instruction but the
// system ones, forward branches and jumps, counted loops, calls and returns, loads and stores into
// a data region of its own, code it patches), storing x0..x31 at checkpoints and each result of
// its straight-line code in a log, then stores the registers in front of the data region. That
// signature, the registers at the end, the data region, the checkpoints and the log, is what the
// two runs must agree on. The body is the same for both
// runs; only the start and the end differ, chosen by the C preprocessor:
//   HTX_QEMU defined:  for qemu-riscv32 (Linux user mode): the signature goes to standard output
//                      by the write system call, then exit(0).
//   otherwise:         for htx_cpu_tb or htx sim: a trap vector that ends the run with SIM_EXIT 3
//                      (no program traps), the end through SYSCTRL SIM_EXIT 0; the signature is
//                      read at `sig` (begin_signature to end_signature for htx sim --signature).
// Both are built with tests/rtl/isa on the include path (htx_test.h's HTX_SIM_EXIT_ADDR) and
// linked by its link.ld at address 0, so PC-relative values (AUIPC, links) agree.
#pragma once

#include <cstdint>
#include <string>

namespace htx::cpu_tb {

inline constexpr uint32_t kRandomProgramRegWords = 32;
inline constexpr uint32_t kRandomProgramDataWords = 256;
// x0..x31 stored at checkpoints through the body as well (a wrong value is seen even when the
// register is written again before the end).
inline constexpr uint32_t kRandomProgramCheckpoints = 12;
// And every result the main body's straight-line code produces, stored through a log pointer
// (x29) as it is produced.
inline constexpr uint32_t kRandomProgramLogWords = 512;
inline constexpr uint32_t kRandomProgramSignatureWords =
    kRandomProgramRegWords * (1 + kRandomProgramCheckpoints) + kRandomProgramDataWords +
    kRandomProgramLogWords;
// The SIM_EXIT code of the trap vector (htx_cpu_tb reports "FAIL (SIM_EXIT 3)").
inline constexpr uint32_t kRandomProgramTrapExit = 3;

// Assembly source (for `gcc -x assembler-with-cpp`) of the program for `seed`; the same seed gives
// the same text on every host (the generator's random numbers are std::mt19937_64's, whose
// sequence the standard fixes, and no standard distribution is used).
std::string random_program(uint64_t seed);

// A signature word's name for messages: "x5", "data[17]", "checkpoint 3 x5", "log[40]".
std::string signature_word_name(uint32_t index);

}  // namespace htx::cpu_tb
