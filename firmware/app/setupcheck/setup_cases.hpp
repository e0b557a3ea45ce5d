// Triangle setup on the target (firmware/app/setupcheck) and on the host (tests/system
// setup_check_test.cpp): the same pseudo-random triangle records and the same fold of every setup
// result into one checksum, so the firmware's setup on the rv32im CPU can be held to the model.
// Freestanding C++17 (compiled into the firmware and into the host test).
#pragma once

#include <stdint.h>

#include "htx/fw/crc32.h"
#include "htx/fw/tri_setup.h"
#include "htx/fw/vertex_record.h"

namespace setupcheck {

// The two named configurations and a screen for each.
struct Config {
  const char* name;
  htx::fw::SetupParams params;
  int32_t width, height;
};
inline constexpr Config kConfigs[2] = {
    {"icebreaker", htx::fw::kIcebreakerSetup, 160, 120},
    {"full", htx::fw::kFullSetup, 640, 480},
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
  const htx::fw::RecordFormat& f = c.params.format;
  const int64_t lim = int64_t{1} << (f.xy_int_bits - 1 + 8);
  const uint32_t kind = g.next() % 8;
  const int64_t uv = (int64_t{1} << (f.uv_int_bits - 1)) - 1;
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
    v.z = g.next() & ((uint32_t{1} << f.z_bits) - 1);
    v.q = static_cast<uint32_t>(g.range(1, (int64_t{1} << f.q_bits) - 1));
    v.uq = g.range(-uv, uv) * static_cast<int64_t>(v.q);
    v.vq = g.range(-uv, uv) * static_cast<int64_t>(v.q);
    v.rgba = g.next();
  }
  r.v[g.next() % 3].q |= uint32_t{1} << (f.q_bits - 1);
  if (g.next() % 16 == 0) r.v[2] = r.v[1];
  return r;
}

// The checksum: CRC-32 over each result as 8 little-endian bytes, in the order the callers give.
inline uint32_t fold(uint32_t crc, uint64_t value) {
  for (int b = 0; b < 8; ++b) crc = htx::fw::crc32_update_byte(crc, static_cast<uint8_t>(value >> (8 * b)));
  return crc;
}

// One configuration's checksum over kTriangles triangles: each result of `setup`, an
// implementation in the firmware's types (the firmware's own, or the model's converted),
//   htx::fw::CoverageSetup coverage(const htx::fw::TriangleRecord&, int32_t width, int32_t height)
//   htx::fw::RecipResult   reciprocal(int64_t det)
//   htx::fw::PlaneSetup    plane(const htx::fw::CoverageSetup&, int plane, htx::fw::RecipResult)
//   int64_t                divide(int64_t num, uint32_t q)
// folded in order. *drawn counts the triangles that reach the planes.
template <class Setup>
uint32_t checksum(const Config& c, Setup& setup, uint32_t* drawn) {
  Lcg gen{2026};
  uint32_t crc = 0;
  *drawn = 0;
  for (uint32_t i = 0; i < kTriangles; ++i) {
    const htx::fw::CoverageSetup s = setup.coverage(make_record(c, gen), c.width, c.height);
    crc = fold(crc, static_cast<uint64_t>(s.det));
    if (s.det == 0) continue;
    crc = fold(crc, s.empty ? 1 : 0);
    crc = fold(crc, static_cast<uint64_t>(s.x_lo) ^ (static_cast<uint64_t>(s.x_hi) << 32));
    crc = fold(crc, static_cast<uint64_t>(s.y_lo) ^ (static_cast<uint64_t>(s.y_hi) << 32));
    for (const htx::fw::SetupEdge& e : s.edges) {
      crc = fold(crc, static_cast<uint64_t>(e.a));
      crc = fold(crc, static_cast<uint64_t>(e.b));
      crc = fold(crc, static_cast<uint64_t>(e.threshold));
    }
    if (s.empty) continue;
    const htx::fw::RecipResult inv = setup.reciprocal(s.det);
    crc = fold(crc, inv.value);
    crc = fold(crc, static_cast<uint64_t>(inv.shift));
    for (int a = 0; a < 8; ++a) {
      const htx::fw::PlaneSetup p = setup.plane(s, a, inv);
      const htx::fw::Int128 words[3] = {p.base, p.gx, p.gy};
      for (const htx::fw::Int128& w : words) {
        crc = fold(crc, w.lo);
        crc = fold(crc, w.hi);
      }
    }
    for (const htx::fw::VertexRecord& v : s.rec.v) {
      crc = fold(crc, static_cast<uint64_t>(setup.divide(v.uq, v.q)));
      crc = fold(crc, static_cast<uint64_t>(setup.divide(v.vq, v.q)));
    }
    ++*drawn;
  }
  return crc;
}

}  // namespace setupcheck
