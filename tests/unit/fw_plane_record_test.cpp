// The firmware's plane records (firmware/lib plane_record.h) against the host model's setup, on
// random `icebreaker` triangles: the box, coverage from the record's edge words and flags at pixels
// of the box, every attribute plane's start value and gradients, AFFINE's u, v planes, DIVFREE's
// side band, and the pairs' layout. (The RTL reading them is tested by every `icebreaker` frame.)
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "htx/fw/plane_record.h"
#include "htx/fw/tri_setup.h"
#include "htx/model/config.hpp"
#include "htx/model/lod.hpp"
#include "htx/model/raster_setup.hpp"
#include "htx/model/recip.hpp"

namespace {

using htx::model::i128;
using htx::model::u128;

constexpr u128 kMask56 = (u128{1} << 56) - 1;

// The record's pairs, by (select, index): the 56-bit word; and where LAST was.
struct Pairs {
  u128 word[3][16] = {};
  bool seen[3][16] = {};
  size_t count = 0;
  bool last_ok = false;
};

Pairs read_pairs(const uint32_t* w, size_t n) {
  Pairs p;
  for (size_t i = 0; i + 1 < n; i += 2) {
    const uint32_t hi = w[i + 1];
    const uint32_t sel = (hi >> htx::fw::kPlaneSelectPos) & 3u, idx = (hi >> htx::fw::kPlaneIndexPos) & 15u;
    EXPECT_LT(sel, 3u);
    EXPECT_FALSE(p.seen[sel][idx]) << "pair sent twice";
    p.word[sel][idx] = (static_cast<u128>(hi & 0xFFFFFFu) << 32) | w[i];
    p.seen[sel][idx] = true;
    ++p.count;
    const bool last = (hi & htx::fw::kPlaneLastBit) != 0;
    EXPECT_EQ(last, i + 2 == n) << "LAST on pair " << i / 2 << " of " << n / 2;
    p.last_ok = last;
  }
  return p;
}

u128 mod56(i128 v) { return static_cast<u128>(v) & kMask56; }

// A random record in the `icebreaker` format, mostly near a 160 x 120 screen.
htx::fw::TriangleRecord random_record(std::mt19937_64& rng, const htx::ModelConfig& cfg) {
  htx::fw::TriangleRecord r;
  const int64_t lim = int64_t{1} << (cfg.xy_int_bits - 1 + 8);
  const int64_t uv = int64_t{1} << (cfg.uv_int_bits - 1);
  const bool sliver = rng() % 6 == 0;
  for (auto& v : r.v) {
    int64_t x = rng() % 5 == 0 ? static_cast<int64_t>(rng() % (2 * lim)) - lim
                               : static_cast<int64_t>(rng() % (200 * 256)) - 20 * 256;
    int64_t y = rng() % 5 == 0 ? static_cast<int64_t>(rng() % (2 * lim)) - lim
                               : static_cast<int64_t>(rng() % (160 * 256)) - 20 * 256;
    if (sliver && &v != &r.v[0]) {
      x = r.v[0].x + static_cast<int64_t>(rng() % 700) - 350;
      y = r.v[0].y + static_cast<int64_t>(rng() % 9000) - 4500;
    }
    v.x = static_cast<int32_t>(std::clamp(x, -lim, lim - 1));
    v.y = static_cast<int32_t>(std::clamp(y, -lim, lim - 1));
    v.z = static_cast<uint32_t>(rng() & ((uint64_t{1} << cfg.z_bits) - 1));
    v.q = static_cast<uint32_t>(1 + rng() % ((uint64_t{1} << cfg.q_bits) - 1));
    v.uq = (static_cast<int64_t>(rng() % (2 * uv - 1)) - uv + 1) * static_cast<int64_t>(v.q);
    v.vq = (static_cast<int64_t>(rng() % (2 * uv - 1)) - uv + 1) * static_cast<int64_t>(v.q);
    v.rgba = static_cast<uint32_t>(rng());
  }
  r.v[rng() % 3].q |= uint32_t{1} << (cfg.q_bits - 1);
  r.u_offset = static_cast<int32_t>(rng() % 4096) - 2048;
  r.v_offset = static_cast<int32_t>(rng() % 4096) - 2048;
  return r;
}

TEST(FwPlaneRecord, FitsTheBoardsFormatsOnly) {
  EXPECT_TRUE(htx::fw::plane_record_fits(htx::fw::kIcebreakerSetup));
  EXPECT_FALSE(htx::fw::plane_record_fits(htx::fw::kFullSetup));
  std::mt19937_64 rng(5);
  const htx::fw::TriangleRecord rec = random_record(rng, htx::model_config("full"));
  htx::fw::PlaneJob job;
  job.params = &htx::fw::kFullSetup;
  job.width = 160;
  job.height = 120;
  uint32_t w[htx::fw::kPlaneRecordMaxWords];
  size_t n = 99;
  EXPECT_EQ(htx::fw::encode_plane_record(job, rec, w, &n), htx::fw::kPlaneTooWide);
  EXPECT_EQ(n, 0u);
}

TEST(FwPlaneRecord, MatchesTheModelsSetup) {
  const htx::ModelConfig& cfg = htx::model_config("icebreaker");
  const htx::fw::SetupParams params = cfg.setup_params();
  const htx::model::RecipParams mp{cfg.recip_table_bits, cfg.recip_guard_bits, cfg.recip_width, cfg.setup_nr_steps};
  const unsigned gf = cfg.grad_frac_bits;
  const unsigned gwu = cfg.q_bits + cfg.uv_int_bits + (cfg.xy_int_bits + 9) + 2 + gf + 1;
  const int width = 160, height = 120;
  std::mt19937_64 rng(2027);
  int drawn = 0, affine = 0, divfree = 0, negative = 0;
  for (int t = 0; t < 6000; ++t) {
    const htx::fw::TriangleRecord rec = random_record(rng, cfg);
    htx::fw::PlaneJob job;
    job.params = &params;
    job.width = width;
    job.height = height;
    job.method = static_cast<uint32_t>(rng() % 5);
    job.texture_planes = rng() % 4 != 0;
    job.state_word = static_cast<uint32_t>(rng());
    uint32_t w[htx::fw::kPlaneRecordMaxWords];
    size_t n = 0;
    const htx::fw::PlaneStatus status = htx::fw::encode_plane_record(job, rec, w, &n);
    const htx::model::TriSetup ms = htx::model::setup_coverage(rec, width, height);
    if (ms.empty) {
      ASSERT_EQ(status, htx::fw::kPlaneEmpty) << "triangle " << t;
      ASSERT_EQ(n, 0u);
      continue;
    }
    ASSERT_EQ(status, htx::fw::kPlaneOk) << "triangle " << t;
    ++drawn;
    const bool df = job.method == 4;
    const size_t planes = job.texture_planes ? 10 : 7;  // edges 0..2, z, r, g, b (q, uq, vq)
    ASSERT_EQ(n, htx::fw::kPlaneHeaderWords + (df ? htx::fw::kPlaneSideWords : 0) + 2 * 3 * planes);
    ASSERT_EQ(w[0], job.state_word);
    ASSERT_EQ(w[1], rec.v[0].rgba);
    ASSERT_EQ(w[2], static_cast<uint32_t>(ms.x_lo) | (static_cast<uint32_t>(ms.x_hi) << 16));
    ASSERT_EQ(w[3], static_cast<uint32_t>(ms.y_lo) | (static_cast<uint32_t>(ms.y_hi) << 16));
    ASSERT_EQ(w[5], static_cast<uint32_t>(rec.u_offset));
    ASSERT_EQ(w[6], static_cast<uint32_t>(rec.v_offset));
    const size_t first_pair = htx::fw::kPlaneHeaderWords + (df ? htx::fw::kPlaneSideWords : 0);
    const Pairs p = read_pairs(w + first_pair, n - first_pair);
    ASSERT_TRUE(p.last_ok);
    ASSERT_EQ(p.count, 3 * planes);

    // Coverage as the traversal decides it from the record (edge words, thresholds, det's sign),
    // against the model's edges, at pixels of the box.
    const uint32_t flags = w[4];
    const bool dneg = (flags & htx::fw::kPlaneFlagDetNeg) != 0;
    negative += dneg;
    for (int k = 0; k < 3; ++k) {
      const i128 a = static_cast<i128>(p.word[0][k] << 72) >> 73;  // 2a: the gradient field is 55:1
      const i128 e0 = static_cast<i128>(p.word[2][k] << 72) >> 72;
      const bool thr = (flags >> (htx::fw::kPlaneFlagThrPos + k)) & 1u;
      const i128 a_given = thr ? -a : a;
      ASSERT_EQ(((flags >> (htx::fw::kPlaneFlagANegPos + k)) & 1u) != 0, a_given < 0);
      ASSERT_EQ(((flags >> (htx::fw::kPlaneFlagAZeroPos + k)) & 1u) != 0, a_given == 0);
      ASSERT_EQ(((flags >> (htx::fw::kPlaneFlagENegPos + k)) & 1u) != 0, e0 < 0);
    }
    for (int s = 0; s < 8; ++s) {
      const int x = ms.x_lo + static_cast<int>(rng() % static_cast<uint64_t>(ms.x_hi - ms.x_lo + 1));
      const int y = ms.y_lo + static_cast<int>(rng() % static_cast<uint64_t>(ms.y_hi - ms.y_lo + 1));
      const int64_t px = 256 * int64_t{x} + 128, py = 256 * int64_t{y} + 128;
      bool model_in = true, record_in = true;
      for (int k = 0; k < 3; ++k) {
        const auto& e = ms.edges[k];
        model_in = model_in && e.a * (px - e.x0) + e.b * (py - e.y0) >= e.threshold;
        const i128 a = static_cast<i128>(p.word[0][k] << 72) >> 73, b = static_cast<i128>(p.word[1][k] << 72) >> 73;
        const i128 e0 = static_cast<i128>(p.word[2][k] << 72) >> 72;
        const i128 v = e0 + 256 * a * (x - ms.x_lo) + 256 * b * (y - ms.y_lo);
        const bool thr = (flags >> (htx::fw::kPlaneFlagThrPos + k)) & 1u;
        record_in = record_in && ((v < 0) == (thr != dneg));
      }
      ASSERT_EQ(record_in, model_in) << "triangle " << t << " pixel " << x << ", " << y;
    }

    // The attribute planes, as the model builds them.
    const htx::model::Reciprocal inv = htx::model::reciprocal(mp, static_cast<u128>(ms.det));
    const htx::model::DetReciprocal d{inv.value, inv.shift};
    const int64_t px0 = 256 * int64_t{ms.x_lo} + 128, py0 = 256 * int64_t{ms.y_lo} + 128;
    const int attrs[7] = {0, 4, 5, 6, 1, 2, 3};  // z, r, g, b, q, uq, vq (fw::plane_value's numbering)
    htx::model::Plane mpl[7];
    for (size_t pl = 0; pl + 3 < planes; ++pl) {
      std::array<i128, 3> v{};
      for (int i = 0; i < 3; ++i) v[i] = htx::fw::plane_value(ms.rec.v[i], attrs[pl]);
      mpl[pl] = htx::model::make_plane(ms, v, d, gf);
    }
    if (job.texture_planes && job.method == 0) {
      ++affine;
      for (int axis = 0; axis < 2; ++axis) {
        std::array<i128, 3> v{};
        for (int i = 0; i < 3; ++i) {
          const auto& vr = ms.rec.v[i];
          v[i] = htx::model::divide_fixed(mp, axis ? vr.vq : vr.uq, vr.q < 1 ? 1 : vr.q, cfg.texcoord_frac_bits);
        }
        const htx::model::Plane uv = htx::model::make_plane(ms, v, d, gf);
        if (axis == 0) mpl[5] = uv; else mpl[6] = uv;
      }
    }
    for (size_t pl = 0; pl + 3 < planes; ++pl) {
      ASSERT_EQ(p.word[0][3 + pl], mod56(2 * mpl[pl].gx)) << "triangle " << t << " plane " << pl;
      ASSERT_EQ(p.word[1][3 + pl], mod56(2 * mpl[pl].gy)) << "triangle " << t << " plane " << pl;
      ASSERT_EQ(p.word[2][3 + pl], mod56(mpl[pl].at(px0, py0))) << "triangle " << t << " plane " << pl;
    }

    // DIVFREE's side band: the model's LOD gradients and their shift, then the six at full width.
    if (df && job.texture_planes) {
      ++divfree;
      const i128 g[6] = {mpl[5].gx, mpl[5].gy, mpl[6].gx, mpl[6].gy, mpl[4].gx, mpl[4].gy};
      const int shift = htx::model::lod_gradient_shift(g, cfg.lod_grad_bits);
      const uint32_t* side = w + htx::fw::kPlaneHeaderWords;
      size_t pos = 0;
      auto bits = [&](unsigned count) {
        u128 v = 0;
        for (unsigned i = 0; i < count; ++i, ++pos) v |= static_cast<u128>((side[pos / 32] >> (pos % 32)) & 1u) << i;
        return v;
      };
      const u128 lod_mask = (u128{1} << cfg.lod_grad_bits) - 1, gwu_mask = (u128{1} << gwu) - 1;
      for (const i128 x : g) ASSERT_EQ(bits(cfg.lod_grad_bits), static_cast<u128>(x >> shift) & lod_mask);
      ASSERT_EQ(bits(8), static_cast<u128>(shift));
      for (const i128 x : g) ASSERT_EQ(bits(gwu), static_cast<u128>(x) & gwu_mask);
    }
  }
  EXPECT_GT(drawn, 2000);
  EXPECT_GT(affine, 200);
  EXPECT_GT(divfree, 200);
  EXPECT_GT(negative, 500);
}

}  // namespace
