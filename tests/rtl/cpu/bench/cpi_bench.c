// CPI benchmark for htx_cpu: the firmware's kind of integer work, compiled at -O2.
//   - Q16.16 4x4 matrix transforms of vertices (MUL/MULH, shifts), with a clip-code test per vertex
//   - CRC-32 (bitwise, reflected polynomial 0xEDB88320) over a buffer
//   - insertion sort of pseudo-random words
// Each kernel checks itself; main returns 0 only if all checks hold. bench_result holds
// {cycles, instret, crc of "123456789", crc of the work buffer, transform checksum, clip count,
//  sort checksum, failures}, with cycles and instret measured around the kernels by the program.
#include <stdint.h>

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

typedef int32_t fix16;  // Q16.16

static fix16 fmul(fix16 a, fix16 b) { return (fix16)(((int64_t)a * b) >> 16); }

static uint32_t lcg_state = 12345u;
static uint32_t lcg(void) {
  lcg_state = lcg_state * 1664525u + 1013904223u;
  return lcg_state;
}

#define NVERT 48
static fix16 verts[NVERT][4];
static fix16 out[NVERT][4];
static fix16 matrix[4][4];

static uint32_t transform_all(uint32_t* clipped) {
  uint32_t sum = 0;
  uint32_t clip = 0;
  for (int v = 0; v < NVERT; ++v) {
    for (int r = 0; r < 4; ++r) {
      fix16 acc = 0;
      for (int c = 0; c < 4; ++c) acc += fmul(matrix[r][c], verts[v][c]);
      out[v][r] = acc;
    }
    // Clip codes against the six planes -w <= x, y, z <= w.
    const fix16 w = out[v][3];
    uint32_t code = 0;
    for (int k = 0; k < 3; ++k) {
      if (out[v][k] > w) code |= 1u << (2 * k);
      if (out[v][k] < -w) code |= 2u << (2 * k);
    }
    if (code) ++clip;
    sum = (sum << 3 | sum >> 29) ^ (uint32_t)out[v][0] ^ (uint32_t)out[v][1] * 3u ^ code;
  }
  *clipped = clip;
  return sum;
}

static uint32_t crc32(const uint8_t* p, uint32_t n) {
  uint32_t crc = 0xFFFFFFFFu;
  for (uint32_t i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int b = 0; b < 8; ++b) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

#define NSORT 96
static uint32_t keys[NSORT];

static void insertion_sort(uint32_t* a, int n) {
  for (int i = 1; i < n; ++i) {
    const uint32_t x = a[i];
    int j = i - 1;
    while (j >= 0 && a[j] > x) {
      a[j + 1] = a[j];
      --j;
    }
    a[j + 1] = x;
  }
}

static uint8_t work[256];

int main(void) {
  uint32_t failures = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix[r][c] = (fix16)((lcg() & 0x3FFFF) - 0x20000);
  for (int v = 0; v < NVERT; ++v) {
    for (int c = 0; c < 3; ++c) verts[v][c] = (fix16)((lcg() & 0x7FFFF) - 0x40000);
    verts[v][3] = 1 << 16;
  }
  for (int i = 0; i < NSORT; ++i) keys[i] = lcg();
  for (int i = 0; i < 256; ++i) work[i] = (uint8_t)lcg();
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

  // Checks: the CRC-32 check value of "123456789" is 0xCBF43926; keys sorted; the transform agrees
  // with a second evaluation that multiplies through 64-bit sums instead of per-term rounding.
  if (crc_check != 0xCBF43926u) failures |= 1;
  uint32_t ksum = 0;
  for (int i = 0; i < NSORT; ++i) {
    if (i > 0 && keys[i - 1] > keys[i]) failures |= 2;
    ksum += keys[i];
  }
  for (int v = 0; v < NVERT; ++v) {
    for (int r = 0; r < 4; ++r) {
      int64_t acc = 0;
      for (int c = 0; c < 4; ++c) acc += ((int64_t)matrix[r][c] * verts[v][c]) >> 16;
      if ((fix16)acc != out[v][r]) failures |= 4;
    }
  }

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
