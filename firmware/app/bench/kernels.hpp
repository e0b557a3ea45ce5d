// Benchmark kernels with the firmware's kind of integer work. Freestanding C++17 (only C headers),
// so the same source builds for the rv32im target (the benchmark) and for the host (the test that
// checks the target's checksums). Each kernel has an untimed prepare step (pseudo-random inputs,
// whose modulo arithmetic would otherwise dominate) and a timed run that returns a checksum.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace htx::bench {

// At most this many vertices or keys, and 4 bytes per item for the CRC.
constexpr unsigned kMaxItems = 1024;

// Q16.16 4x4 matrix times `count` vertices (x, y, z, 1), with 64-bit intermediate products.
void transform_prepare(uint32_t seed, unsigned count);
uint32_t transform_run(unsigned count);
// Frustum outcodes against the six clip planes (-w <= x, y, z <= w) of `count` homogeneous
// vertices, and trivial accept/reject/clip classification of the triangles they form.
void clip_prepare(uint32_t seed, unsigned count);
uint32_t clip_run(unsigned count);
// Table-driven CRC-32 (IEEE 802.3, reflected, poly 0xEDB88320) of `bytes` bytes; the run also
// builds the table.
void crc32_prepare(uint32_t seed, unsigned bytes);
uint32_t crc32_run(unsigned bytes);
// Sorts `count` 32-bit keys (quicksort, insertion sort below 16 keys) and checks the order.
void sort_prepare(uint32_t seed, unsigned count);
uint32_t sort_run(unsigned count);

// CRC-32 of a buffer, exposed so the host can check it against a known vector.
uint32_t crc32(const uint8_t* data, size_t len);

struct KernelSpec {
  const char* name;
  void (*prepare)(uint32_t seed, unsigned n);
  uint32_t (*run)(unsigned n);
  uint32_t seed;
  unsigned n;
};

// The benchmark's workload (n is clamped to the kernel's capacity): the target runs these in
// order and prints each checksum; the host test recomputes them.
extern const KernelSpec kKernels[];
extern const unsigned kKernelCount;

}  // namespace htx::bench
