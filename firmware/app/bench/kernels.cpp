#include "kernels.hpp"

namespace htx::bench {
namespace {

// xorshift32: the same pseudo-random sequence on host and target.
struct Rng {
  uint32_t s;
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return s;
  }
  int32_t range(int32_t lo, int32_t hi) {  // [lo, hi]
    return lo + static_cast<int32_t>(next() % static_cast<uint32_t>(hi - lo + 1));
  }
};

constexpr int32_t kOne = 1 << 16;  // 1.0 in Q16.16

uint32_t mix(uint32_t h, uint32_t v) { return (h ^ v) * 16777619u; }  // FNV-1a step
constexpr uint32_t kFnvBasis = 2166136261u;

int32_t mul_q16(int32_t a, int32_t b) {
  return static_cast<int32_t>((static_cast<int64_t>(a) * b) >> 16);
}

unsigned clamp_items(unsigned n) { return n > kMaxItems ? kMaxItems : n; }

int32_t g_matrix[4][4];
int32_t g_in[kMaxItems][4];
int32_t g_out[kMaxItems][4];
uint8_t g_codes[kMaxItems];
uint32_t g_keys[kMaxItems];
uint8_t g_bytes[kMaxItems * 4];
uint32_t g_crc_table[256];

void insertion_sort(uint32_t* a, int lo, int hi) {
  for (int i = lo + 1; i <= hi; ++i) {
    const uint32_t v = a[i];
    int j = i - 1;
    while (j >= lo && a[j] > v) {
      a[j + 1] = a[j];
      --j;
    }
    a[j + 1] = v;
  }
}

void quick_sort(uint32_t* a, int lo, int hi) {
  while (hi - lo >= 16) {
    const uint32_t pivot = a[lo + (hi - lo) / 2];
    int i = lo;
    int j = hi;
    while (i <= j) {
      while (a[i] < pivot) ++i;
      while (a[j] > pivot) --j;
      if (i <= j) {
        const uint32_t t = a[i];
        a[i] = a[j];
        a[j] = t;
        ++i;
        --j;
      }
    }
    // Recurse into the smaller part and loop on the larger: bounded stack depth.
    if (j - lo < hi - i) {
      quick_sort(a, lo, j);
      lo = i;
    } else {
      quick_sort(a, i, hi);
      hi = j;
    }
  }
  insertion_sort(a, lo, hi);
}

}  // namespace

void transform_prepare(uint32_t seed, unsigned count) {
  count = clamp_items(count);
  Rng rng{seed};
  for (auto& row : g_matrix) {
    for (int32_t& e : row) e = rng.range(-2 * kOne, 2 * kOne);
  }
  for (unsigned v = 0; v < count; ++v) {
    for (int c = 0; c < 3; ++c) g_in[v][c] = rng.range(-100 * kOne, 100 * kOne);
    g_in[v][3] = kOne;
  }
}

uint32_t transform_run(unsigned count) {
  count = clamp_items(count);
  uint32_t h = kFnvBasis;
  for (unsigned v = 0; v < count; ++v) {
    for (int r = 0; r < 4; ++r) {
      int32_t acc = 0;
      for (int c = 0; c < 4; ++c) acc += mul_q16(g_matrix[r][c], g_in[v][c]);
      g_out[v][r] = acc;
      h = mix(h, static_cast<uint32_t>(acc));
    }
  }
  return h;
}

void clip_prepare(uint32_t seed, unsigned count) {
  count = clamp_items(count);
  Rng rng{seed};
  for (unsigned v = 0; v < count; ++v) {
    const int32_t w = rng.range(1 << 12, 1 << 20);
    for (int c = 0; c < 3; ++c) g_in[v][c] = rng.range(-2 * w, 2 * w);
    g_in[v][3] = w;
  }
}

uint32_t clip_run(unsigned count) {
  count = clamp_items(count);
  count -= count % 3;
  for (unsigned v = 0; v < count; ++v) {
    const int32_t x = g_in[v][0], y = g_in[v][1], z = g_in[v][2], w = g_in[v][3];
    uint8_t code = 0;
    if (x < -w) code |= 1;
    if (x > w) code |= 2;
    if (y < -w) code |= 4;
    if (y > w) code |= 8;
    if (z < -w) code |= 16;
    if (z > w) code |= 32;
    g_codes[v] = code;
  }
  uint32_t accepted = 0, rejected = 0, clipped = 0, h = kFnvBasis;
  for (unsigned t = 0; t < count; t += 3) {
    const uint8_t a = g_codes[t], b = g_codes[t + 1], c = g_codes[t + 2];
    if ((a | b | c) == 0) {
      ++accepted;
    } else if ((a & b & c) != 0) {
      ++rejected;
    } else {
      ++clipped;
      // The planes a Sutherland-Hodgman clipper would visit, one at a time.
      uint8_t planes = static_cast<uint8_t>(a | b | c);
      while (planes) {
        h = mix(h, planes);
        planes = static_cast<uint8_t>(planes & (planes - 1));
      }
    }
  }
  return mix(mix(mix(h, accepted), rejected), clipped);
}

uint32_t crc32(const uint8_t* data, size_t len) {
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    g_crc_table[i] = c;
  }
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 0; i < len; ++i) crc = g_crc_table[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

void crc32_prepare(uint32_t seed, unsigned bytes) {
  if (bytes > sizeof g_bytes) bytes = sizeof g_bytes;
  Rng rng{seed};
  for (unsigned i = 0; i < bytes; ++i) g_bytes[i] = static_cast<uint8_t>(rng.next() >> 24);
}

uint32_t crc32_run(unsigned bytes) {
  if (bytes > sizeof g_bytes) bytes = sizeof g_bytes;
  return crc32(g_bytes, bytes);
}

void sort_prepare(uint32_t seed, unsigned count) {
  count = clamp_items(count);
  Rng rng{seed};
  for (unsigned i = 0; i < count; ++i) g_keys[i] = rng.next();
}

uint32_t sort_run(unsigned count) {
  count = clamp_items(count);
  quick_sort(g_keys, 0, static_cast<int>(count) - 1);
  uint32_t h = kFnvBasis;
  for (unsigned i = 0; i < count; ++i) {
    if (i > 0 && g_keys[i - 1] > g_keys[i]) return 0;  // not sorted: a checksum no run expects
    h = mix(h, g_keys[i]);
  }
  return h;
}

const KernelSpec kKernels[] = {
    {"transform", transform_prepare, transform_run, 0x1234567u, 1024},
    {"clip", clip_prepare, clip_run, 0xBADC0DEu, 1023},
    {"crc32", crc32_prepare, crc32_run, 0xC0FFEEu, 4096},
    {"sort", sort_prepare, sort_run, 0x5EED5u, 1024},
};
const unsigned kKernelCount = sizeof kKernels / sizeof kKernels[0];

}  // namespace htx::bench
