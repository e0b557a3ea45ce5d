#include "htx/fw/plane_record.h"

namespace htx::fw {

namespace {

// The 56-bit two's complement word of a plane-RAM value as a pair (low, high without tags).
void put_pair(uint32_t** out, Int128 data, uint32_t index, uint32_t select) {
  uint32_t* w = *out;
  w[0] = static_cast<uint32_t>(data.lo);
  w[1] = (static_cast<uint32_t>(data.lo >> 32) & 0x00FFFFFFu) | (index << kPlaneIndexPos) | (select << kPlaneSelectPos);
  *out = w + 2;
}

// A plane's three words: g_x and g_y as 2g (the RAM's gradient field is bits 55:1), the start
// value at (px, py) as it is.
void put_plane(uint32_t** out, uint32_t index, Int128 gx, Int128 gy, Int128 start) {
  put_pair(out, i128_shl(gx, 1), index, kPlaneGx);
  put_pair(out, i128_shl(gy, 1), index, kPlaneGy);
  put_pair(out, start, index, kPlaneStart);
}

// value(px, py) 2^F of a plane, modulo 2^64 (the RAM keeps 56 bits, and the traversal steps it
// modulo its width: only the low bits matter).
Int128 plane_at(const PlaneSetup& p, int64_t px, int64_t py) {
  const uint64_t v = p.base.lo + p.gx.lo * static_cast<uint64_t>(px - p.x0) + p.gy.lo * static_cast<uint64_t>(py - p.y0);
  return Int128{v, 0};
}

int msb_index_u128(Int128 a) { return a.hi != 0 ? 64 + msb_index_u64(a.hi) : msb_index_u64(a.lo); }

// Appends the low `bits` bits of v (at most 128) at bit position *pos of the zeroed side band,
// as many at a time as fit the current word.
void put_bits(uint32_t* side, uint32_t* pos, Int128 v, uint32_t bits) {
  for (uint32_t i = 0; i < bits;) {
    const uint32_t off = *pos & 31;
    const uint32_t take = (bits - i < 32 - off) ? bits - i : 32 - off;
    const uint64_t chunk = i128_sar(v, i).lo & ((uint64_t{1} << take) - 1);
    side[*pos >> 5] |= static_cast<uint32_t>(chunk) << off;
    *pos += take;
    i += take;
  }
}

}  // namespace

PlaneStatus encode_plane_record(const PlaneJob& job, const TriangleRecord& rec, uint32_t* out, size_t* words) {
  const SetupParams& prm = *job.params;
  *words = 0;
  if (!plane_record_fits(prm)) return kPlaneTooWide;
  CoverageSetup s;
  setup_coverage(rec, job.width, job.height, &s);
  if (s.empty) return kPlaneEmpty;
  const VertexRecord* v = rec.v;  // as given: the unit's edges are not reordered (det_neg)
  const int64_t det = (int64_t{v[1].x} - v[0].x) * (int64_t{v[2].y} - v[0].y) -
                      (int64_t{v[2].x} - v[0].x) * (int64_t{v[1].y} - v[0].y);
  const int64_t px = 256 * int64_t{s.x_lo} + 128, py = 256 * int64_t{s.y_lo} + 128;

  uint32_t* w = out;
  w[0] = job.state_word;
  w[1] = v[0].rgba;
  w[2] = static_cast<uint32_t>(s.x_lo) | (static_cast<uint32_t>(s.x_hi) << 16);
  w[3] = static_cast<uint32_t>(s.y_lo) | (static_cast<uint32_t>(s.y_hi) << 16);
  w[5] = static_cast<uint32_t>(rec.u_offset);
  w[6] = static_cast<uint32_t>(rec.v_offset);
  w += kPlaneHeaderWords;
  const bool divfree = job.method == 4;
  uint32_t* side = w;
  if (divfree) {
    for (size_t i = 0; i < kPlaneSideWords; ++i) side[i] = 0;
    w += kPlaneSideWords;
  }

  // The edges as given, E_k = a_k (px - x_k) + b_k (py - y_k); one whose threshold is 1 (not a
  // top or left edge) goes negated, so that coverage is a sign test. For det < 0 the model
  // reverses every edge, which the unit does from these and det_neg.
  uint32_t flags = det < 0 ? kPlaneFlagDetNeg : 0u;
  for (uint32_t k = 0; k < 3; ++k) {
    const VertexRecord& p = v[k];
    const VertexRecord& q = v[(k + 1) % 3];
    const int64_t a = int64_t{p.y} - q.y, b = int64_t{q.x} - p.x;
    const bool thr = !(a > 0 || (a == 0 && b > 0));
    const int64_t e = a * (px - p.x) + b * (py - p.y);
    const int64_t sgn = thr ? -1 : 1;
    flags |= (thr ? 1u : 0u) << (kPlaneFlagThrPos + k);
    flags |= (a < 0 ? 1u : 0u) << (kPlaneFlagANegPos + k);
    flags |= (a == 0 ? 1u : 0u) << (kPlaneFlagAZeroPos + k);
    flags |= (sgn * e < 0 ? 1u : 0u) << (kPlaneFlagENegPos + k);
    put_plane(&w, k, i128_from(sgn * a), i128_from(sgn * b), i128_from(sgn * e));
  }
  out[4] = flags;

  // The attribute planes through the setup's (reordered) vertices, as the model builds them.
  // (plane_record_fits bounds every value for the *_64 functions; divide_fixed_64 checks its shift.)
  const RecipResult inv = reciprocal_64(prm.recip, s.det);
  const uint32_t gf = prm.grad_frac_bits;
  const VertexRecord* r = s.rec.v;
  int64_t vals[3];
  PlaneSetup planes[7];  // z, r, g, b, q, uq, vq
  const int attr[7] = {0, 4, 5, 6, 1, 2, 3};  // plane_value's numbering
  const int count = job.texture_planes ? 7 : 4;
  for (int p = 0; p < count; ++p) {
    for (int i = 0; i < 3; ++i) vals[i] = plane_value(r[i], attr[p]);
    make_plane_64(s, vals, inv, gf, &planes[p]);
  }
  if (job.texture_planes && job.method == 0) {
    // AFFINE: the vertex texel coordinates u_i = uq_i / q_i, in the places of uq and vq.
    int64_t ua[3], va[3];
    for (int i = 0; i < 3; ++i) {
      const uint64_t q = r[i].q < 1 ? 1 : r[i].q;
      if (!divide_fixed_64(prm.recip, r[i].uq, q, prm.texcoord_frac_bits, &ua[i]) ||
          !divide_fixed_64(prm.recip, r[i].vq, q, prm.texcoord_frac_bits, &va[i]))
        return kPlaneTooWide;
    }
    make_plane_64(s, ua, inv, gf, &planes[5]);
    make_plane_64(s, va, inv, gf, &planes[6]);
  }
  for (int p = 0; p < count; ++p)
    put_plane(&w, 3 + static_cast<uint32_t>(p), planes[p].gx, planes[p].gy, plane_at(planes[p], px, py));
  w[-1] |= kPlaneLastBit;

  if (divfree && job.texture_planes) {
    // DIVFREE's side band: the LOD unit's block-shifted gradients g_ux, g_uy, g_vx, g_vy, g_qx,
    // g_qy (lod_grad_bits each), its shift (8 bits), then the six at full precision (GWU bits).
    const Int128 g[6] = {planes[5].gx, planes[5].gy, planes[6].gx, planes[6].gy, planes[4].gx, planes[4].gy};
    Int128 big{};
    for (const Int128& x : g) {
      const Int128 m = i128_negative(x) ? i128_neg(x) : x;
      if (u128_less(big, m)) big = m;
    }
    const int shift_raw = msb_index_u128(big) + 2 - static_cast<int>(prm.lod_grad_bits);
    const uint32_t shift = shift_raw > 0 ? static_cast<uint32_t>(shift_raw) : 0u;
    const uint32_t gwu = uint32_t{prm.format.q_bits} + prm.format.uv_int_bits + prm.format.xy_int_bits + 8 + 1 + 2 + gf + 1;
    uint32_t pos = 0;
    for (const Int128& x : g) put_bits(side, &pos, i128_sar(x, shift), prm.lod_grad_bits);
    put_bits(side, &pos, u128_from(shift), 8);
    for (const Int128& x : g) put_bits(side, &pos, x, gwu);
  }
  *words = static_cast<size_t>(w - out);
  return kPlaneOk;
}

}  // namespace htx::fw
