// Benchmark firmware: prepares and runs each kernel (kernels.hpp) once, measuring the run's cycles and retired instructions
// with the Zicsr counters, and reports them with the CPI and the kernel's checksum over the UART:
//   bench <name> cycles <c> instret <i> cpi <c/i, 3 decimals> checksum <8 hex digits>
//   bench total cycles <c> instret <i> cpi <x.xxx>
#include <stdint.h>
#include <stdio.h>

#include "kernels.hpp"

namespace {

struct Counters {
  uint64_t cycles;
  uint64_t instret;
};

// Reads the 64-bit counters with the hi/lo/hi sequence, so a carry between the halves is not missed.
uint64_t read_cycle() {
  uint32_t hi, lo, hi2;
  do {
    asm volatile("rdcycleh %0" : "=r"(hi));
    asm volatile("rdcycle %0" : "=r"(lo));
    asm volatile("rdcycleh %0" : "=r"(hi2));
  } while (hi != hi2);
  return (static_cast<uint64_t>(hi) << 32) | lo;
}

uint64_t read_instret() {
  uint32_t hi, lo, hi2;
  do {
    asm volatile("rdinstreth %0" : "=r"(hi));
    asm volatile("rdinstret %0" : "=r"(lo));
    asm volatile("rdinstreth %0" : "=r"(hi2));
  } while (hi != hi2);
  return (static_cast<uint64_t>(hi) << 32) | lo;
}

Counters now() { return {read_cycle(), read_instret()}; }

void report(const char* name, uint64_t cycles, uint64_t instret) {
  const uint64_t milli = instret ? (cycles * 1000u + instret / 2u) / instret : 0;
  printf("bench %s cycles %lu instret %lu cpi %lu.%03lu", name, static_cast<unsigned long>(cycles),
         static_cast<unsigned long>(instret), static_cast<unsigned long>(milli / 1000u),
         static_cast<unsigned long>(milli % 1000u));
}

}  // namespace

int main() {
  printf("hypertex bench: %u kernels\r\n", htx::bench::kKernelCount);
  uint64_t total_cycles = 0, total_instret = 0;
  for (unsigned k = 0; k < htx::bench::kKernelCount; ++k) {
    const htx::bench::KernelSpec& spec = htx::bench::kKernels[k];
    spec.prepare(spec.seed, spec.n);
    const Counters a = now();
    const uint32_t sum = spec.run(spec.n);
    const Counters b = now();
    total_cycles += b.cycles - a.cycles;
    total_instret += b.instret - a.instret;
    report(spec.name, b.cycles - a.cycles, b.instret - a.instret);
    printf(" checksum %08lx\r\n", static_cast<unsigned long>(sum));
  }
  report("total", total_cycles, total_instret);
  printf("\r\n");
  return 0;
}
