// CPI benchmark for htx_cpu: the firmware's kind of integer work, compiled at -O2.
//   - Q16.16 4x4 matrix transforms of vertices (MUL/MULH, shifts), with a clip-code test per vertex
//   - CRC-32 (bitwise, reflected polynomial 0xEDB88320) over a buffer
//   - insertion sort of pseudo-random words
// The kernels and their inputs are cpi_kernels.h. Only the kernels run between the rdcycle/rdinstret
// reads; the checks come after them (check_results, not inlined, so that its code stays out of the
// measured window). The expected results (cpi_bench_expected.h) are the same kernels' results
// computed on the host at build time by cpi_expect.c, so every result the core computes is checked
// against a machine other than the core: the CRC-32 of the work buffer, the transform's checksum,
// clip count and every output word, and the sorted keys word for word. The sort is also checked on
// the core itself for order and for being a permutation of its input (the keys generated again:
// their sum, xor and sum of squares). main returns 0 only if all checks hold. bench_result holds
// {cycles, instret, crc of "123456789", crc of the work buffer, transform checksum, clip count,
//  sort checksum (sum of the keys), failures (a bit per failed check)}, with cycles and instret
// measured around the kernels by the program.
#include <stdint.h>

#include "cpi_bench_expected.h"
#include "cpi_kernels.h"

volatile uint32_t bench_result[8];

static inline uint32_t read_cycle(void) {
  uint32_t v;
  __asm__ volatile("rdcycle %0" : "=r"(v));
  return v;
}
static inline uint32_t read_instret(void) {
  uint32_t v;
  __asm__ volatile("rdinstret %0" : "=r"(v));
  return v;
}

enum {
  kBadCrcCheck = 1,     // CRC-32 of "123456789" is not the standard check value 0xCBF43926
  kNotSorted = 2,       // a key greater than the next
  kBadTransform = 4,    // the transform's output words differ from the host's
  kBadCrcWork = 8,      // CRC-32 of the work buffer differs from the host's
  kBadTsum = 16,        // transform checksum or clip count differs from the host's
  kNotPermutation = 32, // the sorted keys' sum, xor or sum of squares is not the input's
  kBadSorted = 64,      // the sorted keys differ from the host's (its own sort, qsort)
};

// The results' checks, after the measured window.
static __attribute__((noinline)) uint32_t check_results(uint32_t crc_check, uint32_t crc_work, uint32_t tsum,
                                                         uint32_t clipped, uint32_t* ksum_out) {
  uint32_t failures = 0;
  if (crc_check != 0xCBF43926u) failures |= kBadCrcCheck;
  if (crc_work != CPI_EXPECT_CRC_WORK) failures |= kBadCrcWork;
  if (tsum != CPI_EXPECT_TSUM || clipped != CPI_EXPECT_CLIPPED) failures |= kBadTsum;
  if (hash_words((const uint32_t*)out, NVERT * 4) != CPI_EXPECT_OUT_HASH) failures |= kBadTransform;
  uint32_t ksum = 0, kxor = 0, ksq = 0;
  for (int i = 0; i < NSORT; ++i) {
    if (i > 0 && keys[i - 1] > keys[i]) failures |= kNotSorted;
    ksum += keys[i];
    kxor ^= keys[i];
    ksq += keys[i] * keys[i];
  }
  // The input keys again from the LCG (past the matrix's and the vertices' values).
  uint32_t state = CPI_LCG_SEED, isum = 0, ixor = 0, isq = 0;
  for (int i = 0; i < 16 + 3 * NVERT + NSORT; ++i) {
    state = state * 1664525u + 1013904223u;
    if (i >= 16 + 3 * NVERT) {
      isum += state;
      ixor ^= state;
      isq += state * state;
    }
  }
  if (ksum != isum || kxor != ixor || ksq != isq) failures |= kNotPermutation;
  if (hash_words(keys, NSORT) != CPI_EXPECT_SORTED_HASH) failures |= kBadSorted;
  *ksum_out = ksum;
  return failures;
}

int main(void) {
  make_inputs();
  static const uint8_t check_string[9] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};

  const uint32_t c0 = read_cycle();
  const uint32_t i0 = read_instret();
  uint32_t clipped = 0;
  const uint32_t tsum = transform_all(&clipped);
  const uint32_t crc_check = crc32(check_string, 9);
  const uint32_t crc_work = crc32(work, sizeof work);
  insertion_sort(keys, NSORT);
  const uint32_t c1 = read_cycle();
  const uint32_t i1 = read_instret();

  uint32_t ksum = 0;
  const uint32_t failures = check_results(crc_check, crc_work, tsum, clipped, &ksum);

  bench_result[0] = c1 - c0;
  bench_result[1] = i1 - i0;
  bench_result[2] = crc_check;
  bench_result[3] = crc_work;
  bench_result[4] = tsum;
  bench_result[5] = clipped;
  bench_result[6] = ksum;
  bench_result[7] = failures;
  return failures == 0 ? 0 : 1;
}
