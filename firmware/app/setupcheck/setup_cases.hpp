// Triangle setup on the target (firmware/app/setupcheck) and on the host (tests/system
// setup_check_test.cpp): the same pseudo-random triangle records and the same fold of every setup
// result into one checksum, so the firmware's setup on the rv32im CPU can be held to the model.
// Freestanding C++17 (compiled into the firmware and into the host test).
#pragma once

#include <stdint.h>

#include "htx/fw/crc32.h"
#include "htx/fw/vertex_record.h"

namespace setupcheck {

// The two named configurations' record formats and setup parameters (the host test checks them
// against the model's configurations).
struct Config {
  const char* name;
  htx::fw::RecordFormat format;
  uint32_t recip_k, recip_g, recip_width, setup_steps, grad_frac_bits, texcoord_frac_bits;
  int32_t width, height;
};
inline constexpr Config kConfigs[2] = {
    {"icebreaker", {12, 16, 24, 13}, 8, 2, 24, 2, 16, 10, 160, 120},
    {"full", {16, 24, 32, 16}, 10, 2, 32, 2, 24, 16, 640, 480},
};
inline constexpr uint32_t kTriangles = 200;

// A small deterministic generator (64-bit LCG, high bits out).
struct Lcg {
  uint64_t s;
  uint32_t next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<uint32_t>(s >> 32);
  }
  // In [lo, hi].
  int64_t range(int64_t lo, int64_t hi) { return lo + static_cast<int64_t>(next() % static_cast<uint64_t>(hi - lo + 1)); }
};

// Triangle i of a configuration: most near the screen, some anywhere in the coordinate range,
// some slivers, one in sixteen of zero area.
inline htx::fw::TriangleRecord make_record(const Config& c, Lcg& g) {
  htx::fw::TriangleRecord r;
  const int64_t lim = int64_t{1} << (c.format.xy_int_bits - 1 + 8);
  const uint32_t kind = g.next() % 8;
  const int64_t uv = (int64_t{1} << (c.format.uv_int_bits - 1)) - 1;
  for (int k = 0; k < 3; ++k) {
    htx::fw::VertexRecord& v = r.v[k];
    int64_t x, y;
    if (kind == 0) {
      x = g.range(-lim, lim - 1);
      y = g.range(-lim, lim - 1);
    } else if (kind == 1 && k > 0) {
      x = r.v[0].x + g.range(-300, 300);
      y = r.v[0].y + g.range(-300, 300);
    } else {
      x = g.range(-32 * 256, (c.width + 32) * 256);
      y = g.range(-32 * 256, (c.height + 32) * 256);
    }
    v.x = static_cast<int32_t>(x < -lim ? -lim : (x > lim - 1 ? lim - 1 : x));
    v.y = static_cast<int32_t>(y < -lim ? -lim : (y > lim - 1 ? lim - 1 : y));
    v.z = g.next() & ((uint32_t{1} << c.format.z_bits) - 1);
    v.q = static_cast<uint32_t>(g.range(1, (int64_t{1} << c.format.q_bits) - 1));
    v.uq = g.range(-uv, uv) * static_cast<int64_t>(v.q);
    v.vq = g.range(-uv, uv) * static_cast<int64_t>(v.q);
    v.rgba = g.next();
  }
  r.v[g.next() % 3].q |= uint32_t{1} << (c.format.q_bits - 1);
  if (g.next() % 16 == 0) r.v[2] = r.v[1];
  return r;
}

// The checksum: CRC-32 over each result as 8 little-endian bytes, in the order the callers give.
inline uint32_t fold(uint32_t crc, uint64_t value) {
  for (int b = 0; b < 8; ++b) crc = htx::fw::crc32_update_byte(crc, static_cast<uint8_t>(value >> (8 * b)));
  return crc;
}

// The attribute of plane a (0 z, 1 q, 2 uq, 3 vq, 4..7 the colour channels) at a vertex, as a
// signed 64-bit value.
inline int64_t attribute(const htx::fw::VertexRecord& v, int a) {
  switch (a) {
    case 0: return v.z;
    case 1: return v.q;
    case 2: return v.uq;
    case 3: return v.vq;
    default: return (v.rgba >> (8 * (a - 4))) & 0xFF;
  }
}

}  // namespace setupcheck
