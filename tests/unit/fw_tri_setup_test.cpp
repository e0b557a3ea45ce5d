// The firmware's triangle setup (firmware/lib tri_setup.h, int128.h) against the host model's
// (htx/model/raster_setup.hpp, recip.hpp), bit for bit, on random triangles in each named
// configuration's record format: coverage, the determinant's reciprocal, every attribute plane
// and AFFINE's vertex divisions, and (W <= 30) the 64-bit paths the plane records use (make_plane
// takes make_plane_64 wherever the values allow, so its comparison covers that path too).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "htx/fw/int128.h"
#include "htx/fw/tri_setup.h"
#include "htx/model/config.hpp"
#include "htx/model/raster_setup.hpp"
#include "htx/model/recip.hpp"

namespace {

using htx::fw::Int128;
using htx::model::i128;

i128 to_i128(Int128 a) {
  return static_cast<i128>((static_cast<htx::model::u128>(a.hi) << 64) | a.lo);
}
Int128 from_i128(i128 a) {
  const auto u = static_cast<htx::model::u128>(a);
  return Int128{static_cast<uint64_t>(u), static_cast<uint64_t>(u >> 64)};
}

TEST(Int128, MatchesTheCompilersOnRandomOperands) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    // Operands of every width up to 127 bits, both signs.
    const i128 a = static_cast<i128>((static_cast<htx::model::u128>(rng()) << 64) | rng()) >> (rng() % 127);
    const i128 b = static_cast<i128>((static_cast<htx::model::u128>(rng()) << 64) | rng()) >> (rng() % 127);
    const unsigned s = static_cast<unsigned>(rng() % 128);
    const Int128 fa = from_i128(a), fb = from_i128(b);
    ASSERT_EQ(to_i128(htx::fw::i128_add(fa, fb)), static_cast<i128>(static_cast<htx::model::u128>(a) + static_cast<htx::model::u128>(b)));
    ASSERT_EQ(to_i128(htx::fw::i128_sub(fa, fb)), static_cast<i128>(static_cast<htx::model::u128>(a) - static_cast<htx::model::u128>(b)));
    ASSERT_EQ(to_i128(htx::fw::i128_mul(fa, fb)), static_cast<i128>(static_cast<htx::model::u128>(a) * static_cast<htx::model::u128>(b)));
    ASSERT_EQ(to_i128(htx::fw::i128_sar(fa, s)), a >> s);
    ASSERT_EQ(to_i128(htx::fw::i128_shl(fa, s)), static_cast<i128>(static_cast<htx::model::u128>(a) << s));
    ASSERT_EQ(htx::fw::i128_less(fa, fb), a < b);
    const int rs = static_cast<int>(rng() % 140) - 10;
    // Within the model's range (its shift_round checks for overflow: keep a << -s in range).
    const i128 small = a >> 20;
    if (rs >= -10) {
      ASSERT_EQ(to_i128(htx::fw::i128_shift_round(from_i128(small), rs)), htx::model::shift_round(small, rs))
          << "s " << rs;
    }
  }
}

struct Format {
  unsigned xy_int_bits, z_bits, q_bits, uv_int_bits;
};

// A random triangle record as the firmware's encoder can produce it: x, y anywhere in their
// range (most near the screen), the largest q in [2^(q_bits-1), 2^q_bits), uq = (u - offset) q.
htx::fw::TriangleRecord random_record(std::mt19937_64& rng, const Format& f, int width, int height) {
  htx::fw::TriangleRecord r;
  const int64_t xy_lim = int64_t{1} << (f.xy_int_bits - 1 + 8);
  const bool near = rng() % 4 != 0;
  const bool tiny = rng() % 8 == 0;
  std::uniform_int_distribution<int64_t> qd(1, (int64_t{1} << f.q_bits) - 1);
  const int64_t uv_lim = int64_t{1} << (f.uv_int_bits - 1);
  for (auto& v : r.v) {
    int64_t x, y;
    if (near) {
      x = std::uniform_int_distribution<int64_t>(-64 * 256, (width + 64) * 256)(rng);
      y = std::uniform_int_distribution<int64_t>(-64 * 256, (height + 64) * 256)(rng);
    } else {
      x = std::uniform_int_distribution<int64_t>(-xy_lim, xy_lim - 1)(rng);
      y = std::uniform_int_distribution<int64_t>(-xy_lim, xy_lim - 1)(rng);
    }
    if (tiny && &v != &r.v[0]) {  // slivers and near-degenerate triangles
      x = r.v[0].x + static_cast<int64_t>(rng() % 600) - 300;
      y = r.v[0].y + static_cast<int64_t>(rng() % 600) - 300;
    }
    v.x = static_cast<int32_t>(std::clamp(x, -xy_lim, xy_lim - 1));
    v.y = static_cast<int32_t>(std::clamp(y, -xy_lim, xy_lim - 1));
    v.z = static_cast<uint32_t>(rng() & ((uint64_t{1} << f.z_bits) - 1));
    v.q = static_cast<uint32_t>(qd(rng));
    const int64_t u = std::uniform_int_distribution<int64_t>(-uv_lim + 1, uv_lim - 1)(rng);
    const int64_t w = std::uniform_int_distribution<int64_t>(-uv_lim + 1, uv_lim - 1)(rng);
    v.uq = u * static_cast<int64_t>(v.q);
    v.vq = w * static_cast<int64_t>(v.q);
    v.rgba = static_cast<uint32_t>(rng());
  }
  r.v[rng() % 3].q |= static_cast<uint32_t>(uint64_t{1} << (f.q_bits - 1));
  if (rng() % 16 == 0) r.v[2] = r.v[1];  // zero area
  return r;
}

class FwTriSetup : public ::testing::TestWithParam<std::string> {};

TEST_P(FwTriSetup, MatchesTheModelBitForBit) {
  const htx::ModelConfig& cfg = htx::model_config(GetParam());
  const Format f{cfg.xy_int_bits, cfg.z_bits, cfg.q_bits, cfg.uv_int_bits};
  const htx::model::RecipParams mp{cfg.recip_table_bits, cfg.recip_guard_bits, cfg.recip_width, cfg.setup_nr_steps};
  // Half the triangles with the filled table, half computing each entry: both must agree.
  std::vector<uint32_t> table(size_t{1} << cfg.recip_table_bits);
  htx::fw::recip_fill_table(cfg.recip_table_bits, cfg.recip_guard_bits, table.data());
  const htx::fw::RecipSetup fp_tab{cfg.recip_table_bits, cfg.recip_guard_bits, cfg.recip_width, cfg.setup_nr_steps,
                                   table.data()};
  const htx::fw::RecipSetup fp_own{cfg.recip_table_bits, cfg.recip_guard_bits, cfg.recip_width, cfg.setup_nr_steps};
  const int screens[2][2] = {{160, 120}, {4096, 4096}};
  std::mt19937_64 rng(2026);
  int drawn = 0;
  for (int i = 0; i < 20000; ++i) {
    const int width = screens[i % 2][0], height = screens[i % 2][1];
    const htx::fw::TriangleRecord rec = random_record(rng, f, width, height);
    const htx::fw::RecipSetup& fp = (i % 4 < 2) ? fp_tab : fp_own;
    const htx::model::TriSetup ms = htx::model::setup_coverage(rec, width, height);
    htx::fw::CoverageSetup fs;
    htx::fw::setup_coverage(rec, width, height, &fs);
    ASSERT_EQ(fs.det, ms.det) << "triangle " << i;
    if (ms.det == 0) continue;
    ASSERT_EQ(fs.empty, ms.empty) << "triangle " << i;
    ASSERT_EQ(fs.x_lo, ms.x_lo);
    ASSERT_EQ(fs.x_hi, ms.x_hi);
    ASSERT_EQ(fs.y_lo, ms.y_lo);
    ASSERT_EQ(fs.y_hi, ms.y_hi);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(fs.edges[k].a, ms.edges[k].a);
      ASSERT_EQ(fs.edges[k].b, ms.edges[k].b);
      ASSERT_EQ(fs.edges[k].x0, ms.edges[k].x0);
      ASSERT_EQ(fs.edges[k].y0, ms.edges[k].y0);
      ASSERT_EQ(fs.edges[k].threshold, ms.edges[k].threshold);
      ASSERT_EQ(fs.rec.v[k].x, ms.rec.v[k].x);
      ASSERT_EQ(fs.rec.v[k].q, ms.rec.v[k].q);
    }
    if (ms.empty) continue;
    ++drawn;
    const htx::model::Reciprocal mr = htx::model::reciprocal(mp, static_cast<htx::model::u128>(ms.det));
    const htx::fw::RecipResult fr = htx::fw::reciprocal(fp, static_cast<uint64_t>(fs.det));
    ASSERT_EQ(fr.value, mr.value) << "triangle " << i;
    ASSERT_EQ(fr.shift, mr.shift);
    if (cfg.recip_width <= 30) {  // the 64-bit path the plane records take
      const htx::fw::RecipResult f64 = htx::fw::reciprocal_64(fp, static_cast<uint64_t>(fs.det));
      ASSERT_EQ(f64.value, mr.value) << "triangle " << i;
      ASSERT_EQ(f64.shift, mr.shift);
    }
    // Every attribute the raster unit interpolates: z, q, uq, vq, the four colour channels.
    for (int attr = 0; attr < 8; ++attr) {
      std::array<i128, 3> mv{};
      Int128 fv[3];
      for (int k = 0; k < 3; ++k) {
        mv[k] = htx::fw::plane_value(ms.rec.v[k], attr);
        fv[k] = from_i128(mv[k]);
      }
      const htx::model::Plane mpl = htx::model::make_plane(ms, mv, {mr.value, mr.shift}, cfg.grad_frac_bits);
      const htx::fw::PlaneSetup fpl = htx::fw::make_plane(fs, fv, fr, cfg.grad_frac_bits);
      ASSERT_EQ(to_i128(fpl.base), mpl.base) << "triangle " << i << " attribute " << attr;
      ASSERT_EQ(to_i128(fpl.gx), mpl.gx) << "triangle " << i << " attribute " << attr;
      ASSERT_EQ(to_i128(fpl.gy), mpl.gy) << "triangle " << i << " attribute " << attr;
      ASSERT_EQ(fpl.x0, mpl.x0);
      ASSERT_EQ(fpl.y0, mpl.y0);
    }
    // AFFINE's vertex texel coordinates u_i = uq_i / q_i on the setup's reciprocal.
    for (int k = 0; k < 3; ++k) {
      const auto& v = ms.rec.v[k];
      const i128 q = v.q < 1 ? 1 : v.q;
      for (const int64_t num : {v.uq, v.vq}) {
        const int64_t want = htx::model::divide_fixed(mp, num, q, cfg.texcoord_frac_bits);
        ASSERT_EQ(htx::fw::divide_fixed(fp, htx::fw::i128_from(num), static_cast<uint64_t>(q), cfg.texcoord_frac_bits),
                  want)
            << "triangle " << i << " vertex " << k;
        int64_t got = 0;
        if (cfg.recip_width <= 30) {
          ASSERT_TRUE(htx::fw::divide_fixed_64(fp, num, static_cast<uint64_t>(q), cfg.texcoord_frac_bits, &got));
          ASSERT_EQ(got, want) << "triangle " << i << " vertex " << k;
        }
      }
    }
  }
  // The random set must exercise drawn triangles, not only rejected ones.
  EXPECT_GT(drawn, 5000);
}

INSTANTIATE_TEST_SUITE_P(Configs, FwTriSetup, ::testing::Values("icebreaker", "full"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
