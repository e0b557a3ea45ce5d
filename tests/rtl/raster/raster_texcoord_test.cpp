// The texel coordinates the raster RTL sends on its texture request port against the model, fragment
// by fragment: every built-in scene with every built method in both configurations, and random
// triangles with random methods and states (fixed seeds). The expected stream comes from the
// model's TriangleUnit (the spans and span_coords that render_model uses), so every field of each
// request is checked: the level-0 coordinates with the record's offset (wrapped or, for clamp,
// saturated to the port's width), the local coordinates, max(Q, 1) and the block-shifted LOD
// gradients with their shift, the wrap/filter/slot fields and the framebuffer address.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/geometry.hpp"
#include "htx/model/lod.hpp"
#include "htx/model/model.hpp"
#include "htx/model/perspective.hpp"
#include "htx/model/scenes.hpp"
#include "htx/rtl/raster_engine.hpp"
#include "htx/rtl/raster_sim.hpp"
#include "htx_regs.h"
#include "raster_drive.hpp"

namespace htx {
namespace {

using model::i128;

using raster_test::Tri;
using raster_test::encode;
using raster_test::words_of;

raster_test::RtlResult run_rtl(const std::string& name, const std::vector<Tri>& tris, int w, int h) {
  return raster_test::draw(name, tris, w, h, 0, 0xFFFFFFFFu, 24);
}

struct Port {  // the port widths of the named configurations (docs/raster.md)
  unsigned coord_w, loc_w, grad_w;
  // Plane records (`icebreaker`, CAPS.FW_SETUP) carry the LOD gradients for DIVFREE only; the port's
  // LOD gradients and shift are zero for the other methods.
  bool lod_divfree_only;
};
Port port_of(const std::string& cfg) { return cfg == "full" ? Port{48, 32, 24, false} : Port{20, 23, 16, true}; }

int64_t sext(i128 v, unsigned bits) {
  const i128 m = i128{1} << bits;
  i128 r = v % m;
  if (r < 0) r += m;
  if (r >= m / 2) r -= m;
  return static_cast<int64_t>(r);
}

// The port's level-0 coordinate: clamp saturates to CoordW bits, repeat and mirror wrap.
int64_t port_coord(int64_t c, Wrap wrap, unsigned bits) {
  const int64_t hi = (int64_t{1} << (bits - 1)) - 1, lo = -hi - 1;
  if (wrap == Wrap::Clamp) return std::clamp(c, lo, hi);
  return sext(c, bits);
}

// The model's request stream; *divfree_steps (if given) gets the sum of DIVFREE's per-pixel steps
// (render_model's divfree_steps_total, CNT_DIVFREE_STEPS) and *capped the pixels the cap stopped.
std::vector<rtl::TexRequest> expected(const std::vector<Tri>& tris, const ModelConfig& cfg, int w, int h,
                                      const Port& port, uint64_t* divfree_steps = nullptr,
                                      uint64_t* capped = nullptr) {
  std::vector<rtl::TexRequest> out;
  if (divfree_steps) *divfree_steps = 0;
  if (capped) *capped = 0;
  const unsigned tf = cfg.texcoord_frac_bits;
  const model::Log2Unit log2_unit(cfg.lod_log_index_bits, cfg.lod_frac_bits + 2);
  model::SpanCoords span;
  for (const Tri& t : tris) {
    // As render_model: the LOD unit and the texture's last level (0 untextured) for DIVFREE's level
    // choice.
    const model::TriangleUnit unit(t.rec, t.state, cfg, w, h, &log2_unit, t.state.textured ? t.top_level : 0);
    if (unit.empty()) continue;
    const i128 g[6] = {unit.uq_plane().gx, unit.uq_plane().gy, unit.vq_plane().gx,
                       unit.vq_plane().gy, unit.q_plane().gx,  unit.q_plane().gy};
    const int shift = model::lod_gradient_shift(g, cfg.lod_grad_bits);
    for (int y = unit.y_lo(); y <= unit.y_hi(); ++y) {
      int x0 = 0, x1 = -1;
      if (!unit.span(y, &x0, &x1)) continue;
      unit.span_coords(y, x0, x1, t.state.method, &span);
      for (int x = x0; x <= x1; ++x) {
        const size_t k = static_cast<size_t>(x - x0);
        if (t.state.method == Method::DivFree) {
          if (divfree_steps) *divfree_steps += span.divfree_steps[k];
          if (capped) *capped += span.divfree_capped[k];
        }
        rtl::TexRequest r;
        r.u = port_coord(span.u[k] + (int64_t{t.rec.u_offset} << tf), t.state.wrap_u, port.coord_w);
        r.v = port_coord(span.v[k] + (int64_t{t.rec.v_offset} << tf), t.state.wrap_v, port.coord_w);
        r.filter = static_cast<uint8_t>(t.state.filter);
        r.wrap_u = static_cast<uint8_t>(t.state.wrap_u);
        r.wrap_v = static_cast<uint8_t>(t.state.wrap_v);
        r.slot = static_cast<uint8_t>(t.state.texture);
        const int64_t px = 256 * int64_t{x} + 128, py = 256 * int64_t{y} + 128;
        r.lod_q = static_cast<uint64_t>(std::max<i128>(unit.q_plane().at(px, py), 1));
        const bool lod = !port.lod_divfree_only || t.state.method == Method::DivFree;
        for (int i = 0; i < 6; ++i) r.lod_g[i] = lod ? sext(g[i] >> shift, port.grad_w) : 0;
        r.lod_shift = lod ? static_cast<uint32_t>(shift) : 0;
        r.lod_u = sext(span.u[k], port.loc_w);
        r.lod_v = sext(span.v[k], port.loc_w);
        r.addr = static_cast<uint32_t>(y * w + x);
        out.push_back(r);
      }
    }
  }
  return out;
}

// Compares the streams; reports the first difference.
void expect_same(const std::vector<rtl::TexRequest>& rtl, const std::vector<rtl::TexRequest>& ref,
                 const std::string& what) {
  ASSERT_EQ(rtl.size(), ref.size()) << what << ": fragment count";
  for (size_t i = 0; i < ref.size(); ++i) {
    const rtl::TexRequest& a = rtl[i];
    const rtl::TexRequest& b = ref[i];
    bool same = a.u == b.u && a.v == b.v && a.filter == b.filter && a.wrap_u == b.wrap_u && a.wrap_v == b.wrap_v &&
                a.slot == b.slot && a.lod_q == b.lod_q && a.lod_shift == b.lod_shift && a.lod_u == b.lod_u &&
                a.lod_v == b.lod_v && a.addr == b.addr;
    for (int g = 0; g < 6; ++g) same = same && a.lod_g[g] == b.lod_g[g];
    ASSERT_TRUE(same) << what << ": fragment " << i << " (pixel " << b.addr << "): rtl u " << a.u << " v " << a.v
                      << " lod_u " << a.lod_u << " lod_v " << a.lod_v << " q " << a.lod_q << " g0 " << a.lod_g[0]
                      << " shift " << a.lod_shift << " addr " << a.addr << "; model u " << b.u << " v " << b.v
                      << " lod_u " << b.lod_u << " lod_v " << b.lod_v << " q " << b.lod_q << " g0 " << b.lod_g[0]
                      << " shift " << b.lod_shift;
  }
}

const Method kBuilt[] = {Method::Affine, Method::Subdiv, Method::RecipLut, Method::RecipNr, Method::DivFree};
constexpr size_t kNumBuilt = sizeof(kBuilt) / sizeof(kBuilt[0]);

// DIVFREE variants: 0 textured with its filter (bilinear and trilinear choose a level per span up to
// top), 1 textured nearest, 2 untextured (its filter still sets the grid: 2^-divfree_frac_bits
// texels unless nearest, on level 0).
void divfree_variant(Tri* t, unsigned variant, unsigned top) {
  if (t->state.method != Method::DivFree) return;
  t->top_level = top;
  if (variant == 1) t->state.filter = Filter::Nearest;
  if (variant == 2) t->state.textured = false;
}

// Checks the stream and CNT_DIVFREE_STEPS against the model.
void check_run(const std::string& config, const std::vector<Tri>& tris, int w, int h, const std::string& what) {
  const ModelConfig cfg = model_config(config);
  uint64_t steps = 0;
  const raster_test::RtlResult r = run_rtl(config, tris, w, h);
  expect_same(r.requests, expected(tris, cfg, w, h, port_of(config), &steps), what);
  EXPECT_EQ(r.divfree_steps, steps) << what << ": CNT_DIVFREE_STEPS";
}

struct SceneCase {
  std::string config, scene;
};

class TexcoordScenes : public ::testing::TestWithParam<SceneCase> {};

// Every built method on the scene: the triangles take the methods in turn (triangle i the method
// (i + pass) mod 5), five passes, so each triangle is drawn with each method (DIVFREE: the variants
// of divfree_variant in turn, with the scene texture's last level).
TEST_P(TexcoordScenes, EveryMethodMatchesModel) {
  const SceneCase& c = GetParam();
  constexpr int kW = 80, kH = 60;
  const ModelConfig cfg = model_config(c.config);
  ScreenScene screen = prepare_screen_scene(make_builtin_scene(c.scene), kW, kH);
  std::vector<Tri> base = encode(screen, cfg);
  ASSERT_FALSE(base.empty());
  for (int pass = 0; pass < static_cast<int>(kNumBuilt); ++pass) {
    std::vector<Tri> tris = base;
    for (size_t i = 0; i < tris.size(); ++i) {
      TriState& st = tris[i].state;
      st.textured = true;
      st.method = kBuilt[(i + static_cast<size_t>(pass)) % kNumBuilt];
      st.subdiv_n = 2 + static_cast<unsigned>((i * 7 + static_cast<size_t>(pass) * 13) % 63);
      if (!cfg.has_filter(st.filter)) st.filter = Filter::Bilinear;
      const unsigned top = st.texture >= 0 && static_cast<size_t>(st.texture) < screen.textures.size()
                               ? level_count(screen.textures[static_cast<size_t>(st.texture)]) - 1
                               : 0;
      divfree_variant(&tris[i], static_cast<unsigned>(i % 3), top);
    }
    check_run(c.config, tris, kW, kH, c.config + " " + c.scene + " pass " + std::to_string(pass));
  }
}

std::vector<SceneCase> scene_cases() {
  std::vector<SceneCase> cases;
  for (const char* cfg : {"full", "icebreaker"})
    for (const SceneInfo& s : builtin_scenes()) cases.push_back({cfg, s.name});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(All, TexcoordScenes, ::testing::ValuesIn(scene_cases()),
                         [](const ::testing::TestParamInfo<SceneCase>& i) {
                           return i.param.config + "_" + i.param.scene;
                         });

// Random triangles: positions tiny to huge, on and off the screen, random w (perspective), random
// texel coordinates far from the origin (large offsets), random methods, subdivision lengths,
// filters, wraps and slots.
std::vector<Tri> random_tris(uint32_t seed, int n, int w, int h, const ModelConfig& cfg) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ScreenScene s;
  for (int i = 0; i < n; ++i) {
    ScreenTri t;
    const int cls = static_cast<int>(rng() % 8);
    const double spread = cls < 5 ? 5.0 : (cls < 7 ? 24.0 : (rng() % 4 == 0 ? 600.0 : 40.0));
    const double cx = unit(rng) * (w + 20) - 10, cy = unit(rng) * (h + 20) - 10;
    const double ubase = (unit(rng) - 0.5) * (rng() % 4 == 0 ? 60000.0 : 600.0);
    const double vbase = (unit(rng) - 0.5) * (rng() % 4 == 0 ? 60000.0 : 600.0);
    const double tspan = rng() % 3 == 0 ? 2000.0 : 60.0;
    for (ScreenVertex& v : t.v) {
      v.x = cx + (unit(rng) - 0.5) * spread;
      v.y = cy + (unit(rng) - 0.5) * spread;
      v.z = unit(rng);
      v.w = rng() % 2 ? 0.2 + unit(rng) * 20 : 1.0 + unit(rng) * 0.5;
      v.u = ubase + (unit(rng) - 0.5) * tspan;
      v.v = vbase + (unit(rng) - 0.5) * tspan;
      v.r = unit(rng); v.g = unit(rng); v.b = unit(rng); v.a = unit(rng);
    }
    t.state.textured = true;
    t.state.method = kBuilt[rng() % kNumBuilt];
    t.state.subdiv_n = 2 + rng() % 63;
    t.state.filter = static_cast<Filter>(rng() % 3);
    if (!cfg.has_filter(t.state.filter)) t.state.filter = Filter::Nearest;
    const unsigned variant = rng() % 4;  // DIVFREE: 0 and 3 keep the random filter
    if (t.state.method == Method::DivFree && variant == 1) t.state.filter = Filter::Nearest;
    if (t.state.method == Method::DivFree && variant == 2) t.state.textured = false;
    t.state.wrap_u = static_cast<Wrap>(rng() % 3);
    t.state.wrap_v = static_cast<Wrap>(rng() % 3);
    t.state.texture = static_cast<int>(rng() % 8);
    t.state.depth_func = DepthFunc::Always;
    s.tris.push_back(t);
  }
  std::vector<Tri> tris = encode(s, cfg);
  // DIVFREE's texture top level, 0..8, a function of the triangle's random state.
  for (Tri& t : tris) t.top_level = t.state.method == Method::DivFree ? (t.state.subdiv_n * 5 + t.state.texture) % 9 : 0;
  return tris;
}

class TexcoordRandom : public ::testing::TestWithParam<std::string> {};

TEST_P(TexcoordRandom, FiveThousandTrianglesPerConfigMatchModel) {
  const ModelConfig cfg = model_config(GetParam());
  constexpr int kW = 64, kH = 48;
  size_t sent = 0;
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    const std::vector<Tri> tris = random_tris(seed, 1000, kW, kH, cfg);
    sent += tris.size();
    check_run(GetParam(), tris, kW, kH, GetParam() + " seed " + std::to_string(seed));
  }
  EXPECT_GE(sent, 4500u);
}

INSTANTIATE_TEST_SUITE_P(Configs, TexcoordRandom, ::testing::Values("full", "icebreaker"));

// DIVFREE at its cap: small triangles with strong perspective and thousands of texels across a
// few dozen pixels, so the texture moves by more than divfree_cap cells between neighbouring
// pixels or rows where the predictors cannot follow. The capped pixels take the divided cell; the
// stream and CNT_DIVFREE_STEPS must equal the model's, and the model must report capped pixels.
class TexcoordDivfreeCap : public ::testing::TestWithParam<std::string> {};

TEST_P(TexcoordDivfreeCap, CappedPixelsAndStepsMatchModel) {
  const ModelConfig cfg = model_config(GetParam());
  constexpr int kW = 64, kH = 48;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ScreenScene s;
  for (int i = 0; i < 60; ++i) {
    ScreenTri t;
    const double cx = 8 + unit(rng) * (kW - 16), cy = 8 + unit(rng) * (kH - 16);
    for (int k = 0; k < 3; ++k) {
      ScreenVertex& v = t.v[k];
      v.x = cx + (unit(rng) - 0.5) * 40;
      v.y = cy + (unit(rng) - 0.5) * 40;
      v.z = unit(rng);
      v.w = k == 0 ? 0.05 + unit(rng) * 0.1 : 2.0 + unit(rng) * 20;
      v.u = (unit(rng) - 0.5) * 7000;
      v.v = (unit(rng) - 0.5) * 7000;
      v.r = v.g = v.b = v.a = 1.0;
    }
    t.state.textured = i % 3 != 2;
    t.state.method = Method::DivFree;
    t.state.filter = i % 3 == 0 ? Filter::Nearest : Filter::Bilinear;  // textured bilinear: a level per span
    t.state.wrap_u = Wrap::Repeat;
    t.state.wrap_v = Wrap::Mirror;
    t.state.depth_func = DepthFunc::Always;
    s.tris.push_back(t);
  }
  std::vector<Tri> tris = encode(s, cfg);
  for (Tri& t : tris) t.top_level = 7;  // a 128-texel texture's chain
  ASSERT_GE(tris.size(), 40u);
  uint64_t steps = 0, capped = 0;
  const std::vector<rtl::TexRequest> ref = expected(tris, cfg, kW, kH, port_of(GetParam()), &steps, &capped);
  const raster_test::RtlResult r = run_rtl(GetParam(), tris, kW, kH);
  expect_same(r.requests, ref, GetParam() + " cap");
  EXPECT_EQ(r.divfree_steps, steps) << "CNT_DIVFREE_STEPS";
  EXPECT_GE(capped, 10u) << "the scene must reach the cap";
  EXPECT_GE(steps, 64 * capped) << "capped pixels walk the whole cap";
  std::printf("[ divfree ] %s: %zu fragments, %llu capped, %llu steps (CNT_DIVFREE_STEPS %llu)\n",
              GetParam().c_str(), ref.size(), static_cast<unsigned long long>(capped),
              static_cast<unsigned long long>(steps), static_cast<unsigned long long>(r.divfree_steps));
}

INSTANTIATE_TEST_SUITE_P(Configs, TexcoordDivfreeCap, ::testing::Values("full", "icebreaker"));

// An abort while DIVFREE works on a textured bilinear triangle (its walk, a division or a level
// choice in flight), at several moments, then a clean set of DIVFREE triangles in the same unit:
// the unit goes idle and the new stream equals the model's (nothing of the aborted triangle, e.g. a
// LOD result, leaks into the next).
class TexcoordDivfreeAbort : public ::testing::TestWithParam<std::string> {};

std::vector<Tri> divfree_tris(const ModelConfig& cfg, uint32_t seed, int n, double spread) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ScreenScene s;
  for (int i = 0; i < n; ++i) {
    ScreenTri t;
    for (int k = 0; k < 3; ++k) {
      ScreenVertex& v = t.v[k];
      v.x = 32 + (unit(rng) - 0.5) * spread;
      v.y = 24 + (unit(rng) - 0.5) * spread;
      v.z = unit(rng);
      v.w = 0.3 + unit(rng) * 8;
      v.u = (unit(rng) - 0.5) * 900;
      v.v = (unit(rng) - 0.5) * 900;
    }
    t.state.textured = true;
    t.state.method = Method::DivFree;
    t.state.filter = Filter::Bilinear;
    t.state.depth_func = DepthFunc::Always;
    s.tris.push_back(t);
  }
  std::vector<Tri> tris = encode(s, cfg);
  for (Tri& t : tris) t.top_level = 6;
  return tris;
}

TEST_P(TexcoordDivfreeAbort, AbortThenCleanStreamMatchesModel) {
  const std::string name = GetParam();
  const ModelConfig cfg = model_config(name);
  constexpr int kW = 64, kH = 48;
  std::vector<Tri> big = divfree_tris(cfg, 5, 1, 50.0);
  {  // one triangle over the whole screen, in strong perspective
    ScreenScene sc;
    ScreenTri t;
    const double xs[3] = {-100, 200, 20}, ys[3] = {-80, -60, 180}, ws[3] = {0.3, 4.0, 9.0};
    for (int k = 0; k < 3; ++k) {
      t.v[k].x = xs[k];
      t.v[k].y = ys[k];
      t.v[k].w = ws[k];
      t.v[k].u = 700.0 * k;
      t.v[k].v = 300.0 * (2 - k);
    }
    t.state.textured = true;
    t.state.method = Method::DivFree;
    t.state.filter = Filter::Bilinear;
    sc.tris.push_back(t);
    big = encode(sc, cfg);
    for (Tri& b : big) b.top_level = 6;
  }
  const std::vector<Tri> clean = divfree_tris(cfg, 9, 6, 50.0);
  ASSERT_EQ(big.size(), 1u);
  ASSERT_GE(clean.size(), 4u);
  rtl::RasterSim sim(name);
  sim.write_reg(HTX_TEST_REG(FB_SIZE), (uint32_t{kW} << RASTER_FB_SIZE_WIDTH_Pos) |
                                           (uint32_t{kH} << RASTER_FB_SIZE_HEIGHT_Pos));
  sim.write_reg(HTX_TEST_REG(FB_STRIDE), kW);
  sim.write_reg(HTX_TEST_REG(CTRL), RASTER_CTRL_ENABLE_Msk);
  const rtl::FifoRecords form = raster_test::fifo_form(sim, name, kW, kH);
  // Every clock of a stretch of drawing (a span start, its level choice and walk fall inside it),
  // and a few moments further on.
  std::vector<unsigned> waits;
  for (unsigned w = 120; w < 185; ++w) waits.push_back(w);
  for (unsigned w : {60u, 233u, 389u, 577u}) waits.push_back(w);
  for (const unsigned wait : waits) {
    sim.push_words(words_of(big, form));
    sim.idle(wait);
    ASSERT_TRUE(sim.read_reg(HTX_TEST_REG(STATUS)) & RASTER_STATUS_BUSY_Msk) << name << " " << wait;
    sim.write_reg(HTX_TEST_REG(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_ABORT_Msk);
    sim.idle(16);
    EXPECT_EQ(sim.read_reg(HTX_TEST_REG(STATUS)) & RASTER_STATUS_BUSY_Msk, 0u) << name << " " << wait;
    std::vector<rtl::TexRequest> got;
    sim.write_reg(HTX_TEST_REG(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_COUNTERS_RESET_Msk);
    sim.record_requests(&got);
    sim.push_words(words_of(clean, form));
    sim.wait_idle(10'000'000);
    sim.record_requests(nullptr);
    uint64_t steps = 0;
    expect_same(got, expected(clean, cfg, kW, kH, port_of(name), &steps), name + " after abort " + std::to_string(wait));
    EXPECT_EQ(sim.read_reg(HTX_TEST_REG(CNT_DIVFREE_STEPS)), steps) << name << " " << wait;
    EXPECT_EQ(sim.read_reg(HTX_TEST_REG(STATUS)) & RASTER_STATUS_ERR_STATE_Msk, 0u) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(Configs, TexcoordDivfreeAbort, ::testing::Values("full", "icebreaker"));

}  // namespace
}  // namespace htx
