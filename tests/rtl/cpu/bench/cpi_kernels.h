// The CPI benchmark's inputs and kernels, shared by the rv32im benchmark (cpi_bench.c) and the host
// program that computes its expected results (cpi_expect.c, built and run by the host compiler at
// build time): the same C source on another compiler and another machine, so the benchmark's
// checks do not depend on the core under test. Plain C: int32_t arithmetic, arithmetic right shifts
// of negative values (GCC on both), no library calls.
#ifndef CPI_KERNELS_H
#define CPI_KERNELS_H

#include <stdint.h>

typedef int32_t fix16;  // Q16.16

static fix16 fmul(fix16 a, fix16 b) { return (fix16)(((int64_t)a * b) >> 16); }

#define CPI_LCG_SEED 12345u
static uint32_t lcg_state = CPI_LCG_SEED;
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

#define NWORK 256
static uint8_t work[NWORK];

// The inputs, in this order from the LCG: the matrix, the vertices, the keys, the work buffer.
static void make_inputs(void) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix[r][c] = (fix16)((lcg() & 0x3FFFF) - 0x20000);
  for (int v = 0; v < NVERT; ++v) {
    for (int c = 0; c < 3; ++c) verts[v][c] = (fix16)((lcg() & 0x7FFFF) - 0x40000);
    verts[v][3] = 1 << 16;
  }
  for (int i = 0; i < NSORT; ++i) keys[i] = lcg();
  for (int i = 0; i < NWORK; ++i) work[i] = (uint8_t)lcg();
}

// An order-sensitive hash of n words (every word and its position count).
static uint32_t hash_words(const uint32_t* p, int n) {
  uint32_t h = 2166136261u;
  for (int i = 0; i < n; ++i) h = (h ^ p[i]) * 16777619u + (uint32_t)i;
  return h;
}

#endif
