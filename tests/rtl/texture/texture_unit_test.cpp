// The texture unit against the model (label `rtl`), bit for bit: every request's filtered texel, level
// and LOD compared with htx::model::sample() / compute_lod(). Checkerboard texel centres, edges and
// corners; wrap seams in every mode; every built format; LOD across the `floor` scene's minified
// plane; random LOD inputs and random requests under output back-pressure; measured throughput.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/geometry.hpp"
#include "htx/model/lod.hpp"
#include "htx/model/model.hpp"
#include "htx/model/perspective.hpp"
#include "htx/model/proc_textures.hpp"
#include "htx/model/sampler.hpp"
#include "htx/model/scenes.hpp"
#include "texture_harness.hpp"

namespace htx {
namespace {

using rtl::TexRequest;
using rtl::TexResult;
using rtl::TexRunReads;
using rtl::TextureHarness;

uint32_t pack(Rgba8 c) {
  return c.r | (uint32_t{c.g} << 8) | (uint32_t{c.b} << 16) | (uint32_t{c.a} << 24);
}

struct Expected {
  uint32_t rgba = 0;
  unsigned level = 0;
  int32_t lod = 0;
};

// What the model's fragment stage does with a request (render_model): the LOD clamped to the
// texture's levels (all-zero derivatives: 0), then sample().
Expected model_sample(const Texture& tex, const ModelConfig& cfg, const TexRequest& r) {
  model::SampleRequest s;
  s.coord = {r.u, r.v, cfg.texcoord_frac_bits};
  s.filter = r.filter;
  s.wrap_u = r.wrap_u;
  s.wrap_v = r.wrap_v;
  s.lod_frac_bits = cfg.lod_frac_bits;
  int32_t lod = r.lod;
  if (!r.lod_direct) {
    static const model::Log2Unit* units[2] = {nullptr, nullptr};
    const int k = cfg.name == "full" ? 0 : 1;
    if (!units[k]) units[k] = new model::Log2Unit(cfg.lod_log_index_bits, cfg.lod_frac_bits + 2);
    model::LodInputs in;
    in.q = std::max<model::i128>(r.q, 1);
    in.gux = r.g[0];
    in.guy = r.g[1];
    in.gvx = r.g[2];
    in.gvy = r.g[3];
    in.gqx = r.g[4];
    in.gqy = r.g[5];
    in.grad_shift = static_cast<int>(r.grad_shift);
    in.u = r.lu;
    in.v = r.lv;
    in.tex_frac_bits = cfg.texcoord_frac_bits;
    lod = model::compute_lod(*units[k], in, cfg.lod_frac_bits);
  }
  const int32_t top = static_cast<int32_t>(level_count(tex) - 1) << cfg.lod_frac_bits;
  s.lod = lod == INT32_MIN ? 0 : std::clamp(lod, 0, top);
  Expected e;
  e.rgba = pack(model::sample(tex, s, &e.level));
  e.lod = s.lod;
  return e;
}

// The icebreaker unit takes coordinates reduced to its CoordW bits by the producer (docs/texture.md):
// wrapped for repeat/mirror, saturated for clamp. The model sees the original coordinate.
int64_t reduce(int64_t c, Wrap w, unsigned bits) {
  if (bits >= 64) return c;
  const int64_t lo = -(int64_t{1} << (bits - 1)), hi = (int64_t{1} << (bits - 1)) - 1;
  if (w == Wrap::Clamp) return std::clamp(c, lo, hi);
  return c;  // the harness drops the bits above CoordW (two's complement wrap)
}

struct Check {
  size_t bad = 0;
  std::string first;
};

// Runs the requests and compares each result with the model.
Check run_and_compare(TextureHarness& h, const ModelConfig& cfg, const std::vector<const Texture*>& slots,
                      const std::vector<TexRequest>& reqs, unsigned stall = 0, uint32_t seed = 1,
                      TexRunReads* reads = nullptr) {
  std::vector<TexRequest> sent = reqs;
  for (TexRequest& r : sent) {
    r.u = reduce(r.u, r.wrap_u, h.coord_bits());
    r.v = reduce(r.v, r.wrap_v, h.coord_bits());
  }
  const std::vector<TexResult> got = h.run(sent, stall, seed, nullptr, reads);
  Check c;
  std::set<uint32_t> distinct;
  for (size_t i = 0; i < reqs.size(); ++i) {
    const TexRequest& r = reqs[i];
    const Expected e = model_sample(*slots[r.slot], cfg, r);
    const TexResult& g = got[i];
    distinct.insert(e.rgba);
    const bool lod_ok = r.filter != Filter::Trilinear || g.lod == static_cast<unsigned>(e.lod);
    if (g.tag != i || g.rgba != e.rgba || g.level != e.level || !lod_ok) {
      if (!c.bad) {
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "request %zu (u %lld v %lld filter %d wrap %d/%d slot %u lod %d): rtl tag %u rgba %08x level %u "
                      "lod %u, model rgba %08x level %u lod %d",
                      i, static_cast<long long>(r.u), static_cast<long long>(r.v), static_cast<int>(r.filter),
                      static_cast<int>(r.wrap_u), static_cast<int>(r.wrap_v), r.slot, r.lod, g.tag, g.rgba, g.level,
                      g.lod, e.rgba, e.level, e.lod);
        c.first = buf;
      }
      ++c.bad;
    }
  }
  // A comparison against a constant would prove nothing.
  if (reqs.size() > 16 && distinct.size() < 2) {
    ++c.bad;
    c.first = "every expected texel is the same: the test cannot tell texels apart";
  }
  return c;
}

std::vector<Filter> built_filters(const ModelConfig& cfg) {
  std::vector<Filter> f;
  for (Filter x : {Filter::Nearest, Filter::Bilinear, Filter::Trilinear})
    if (cfg.has_filter(x)) f.push_back(x);
  return f;
}

class TextureUnit : public ::testing::TestWithParam<std::string> {
 protected:
  const ModelConfig& cfg() const { return model_config(GetParam()); }
};

TEST_P(TextureUnit, RegistersAndWindow) {
  TextureHarness h(GetParam());
  const uint32_t caps = h.reg_read(0x000);
  EXPECT_EQ(caps & 7u, cfg().formats);
  EXPECT_EQ((caps >> 4) & 7u, cfg().filters);
  // Size fields clamp into 3..8 (width 15 -> 8, height 0 -> 3); base and format are kept.
  h.reg_write(0x100, 0x0F1234 | (1u << 24));
  EXPECT_EQ(h.reg_read(0x100), 0x1u << 24 | 3u << 20 | 8u << 16 | 0x1234u);
  // A texel written through the window reads back; a word beyond the memory is an error.
  EXPECT_FALSE(h.mem_write(0x40, 0xBEEF));
  uint32_t v = 0;
  EXPECT_FALSE(h.mem_read(0x40, &v));
  EXPECT_EQ(v & 0xFFFF, 0xBEEFu);
  const unsigned block_bits = (caps >> 16) & 31;
  EXPECT_TRUE(h.mem_write(16u << block_bits, 1));
  EXPECT_TRUE(h.mem_read(16u << block_bits, &v));
  EXPECT_EQ(v, 0u);
  // A partial write of the texel is refused.
  EXPECT_TRUE(h.mem_write(0x40, 0x1111, 0x1));
  EXPECT_FALSE(h.mem_read(0x40, &v));
  EXPECT_EQ(v & 0xFFFF, 0xBEEFu);
}

// Every texel centre, edge and corner (and one coordinate ulp either side of each edge) of a 64x64
// checkerboard, one texel beyond the texture on each side.
TEST_P(TextureUnit, CheckerboardCentresEdgesCorners) {
  const ModelConfig& c = cfg();
  const unsigned tf = c.texcoord_frac_bits;
  TextureHarness h(GetParam());
  const Texture tex = checkerboard_texture(TexFormat::RGB565, 6, 0, Rgba8{250, 30, 10, 255}, Rgba8{5, 90, 240, 255});
  h.upload(tex, 0, 0);
  std::vector<int64_t> coords;
  const int64_t one = int64_t{1} << tf;
  for (int64_t i = -1; i <= 65; ++i) {
    coords.push_back(i * one - 1);
    coords.push_back(i * one);
    coords.push_back(i * one + 1);
    coords.push_back(i * one + one / 2);
  }
  for (Filter f : built_filters(c)) {
    std::vector<TexRequest> reqs;
    std::mt19937 rng(7);
    for (int64_t v : coords)
      for (int64_t u : coords) {
        TexRequest r;
        r.u = u;
        r.v = v;
        r.filter = f;
        r.lod = static_cast<int32_t>(rng() % (7u << c.lod_frac_bits));
        reqs.push_back(r);
      }
    const Check k = run_and_compare(h, c, {&tex}, reqs);
    EXPECT_EQ(k.bad, 0u) << "filter " << static_cast<int>(f) << ": " << k.first;
  }
}

// Coordinates around every seam of a 32x16 texture (non-square, so the axes differ) in each wrap
// mode, from two periods below to two above, and far away.
// Coordinates around every seam of a 2^log2_w x 2^log2_h texture, from two periods below to three
// above and 1000 and 7777 periods away, in every wrap mode on each axis and every built filter.
Check wrap_seams(const std::string& config, const ModelConfig& c, unsigned log2_w,
                 unsigned log2_h) {
  const unsigned tf = c.texcoord_frac_bits;
  TextureHarness h(config);
  const Texture tex =
      make_texture(TexFormat::RGBA4444, log2_w, log2_h, gradient_pixels(log2_w, log2_h));
  h.upload(tex, 1, 0);
  const int64_t one = int64_t{1} << tf;
  auto seam_coords = [&](int64_t size) {
    std::vector<int64_t> v;
    for (int64_t k = -2; k <= 3; ++k)
      for (int64_t d : std::vector<int64_t>{-one, -one / 2, -1, 0, 1, one / 2})
        v.push_back(k * size * one + d);
    for (int64_t far : {int64_t{1000}, int64_t{-1000}, int64_t{7777}})
      v.push_back(far * size * one + one / 4);
    return v;
  };
  const std::vector<int64_t> us = seam_coords(int64_t{1} << log2_w);
  const std::vector<int64_t> vs = seam_coords(int64_t{1} << log2_h);
  std::mt19937 rng(11);
  std::vector<TexRequest> reqs;
  for (Filter f : built_filters(c))
    for (Wrap wu : {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror})
      for (Wrap wv : {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror})
        for (int64_t v : vs)
          for (int64_t u : us) {
            TexRequest r;
            r.u = u;
            r.v = v;
            r.filter = f;
            r.wrap_u = wu;
            r.wrap_v = wv;
            r.slot = 1;
            r.lod = static_cast<int32_t>(rng() % (6u << c.lod_frac_bits));
            reqs.push_back(r);
          }
  return run_and_compare(h, c, {&tex, &tex}, reqs);
}

TEST_P(TextureUnit, WrapSeams) {
  const Check k = wrap_seams(GetParam(), cfg(), 5, 4);
  EXPECT_EQ(k.bad, 0u) << k.first;
}

// The largest texture side (256): mirror's period is then 512 texels, the most integer bits of
// the coordinate that wrapping uses (icebreaker's CoordW keeps those and one more: it fails with
// two fewer, docs/texture.md).
TEST_P(TextureUnit, WrapSeamsOfTheLargestSize) {
  const Check k = wrap_seams(GetParam(), cfg(), 8, 3);
  EXPECT_EQ(k.bad, 0u) << k.first;
}

// Every built format: random texels, sizes, coordinates, filters and wraps.
TEST_P(TextureUnit, EveryFormatRandom) {
  const ModelConfig& c = cfg();
  TextureHarness h(GetParam());
  std::mt19937 rng(23);
  std::vector<Texture> texs;
  for (TexFormat f : {TexFormat::RGB565, TexFormat::RGBA4444, TexFormat::RGBA8888}) {
    if (!c.has_format(f)) continue;
    const unsigned a = 3 + rng() % 4, b = 3 + rng() % 4;
    std::vector<uint8_t> px(size_t{4} << (a + b));
    for (uint8_t& x : px) x = static_cast<uint8_t>(rng());
    texs.push_back(make_texture(f, a, b, px));
  }
  std::vector<const Texture*> slots;
  uint32_t base = 0;
  for (size_t s = 0; s < texs.size(); ++s) {
    base += h.upload(texs[s], static_cast<unsigned>(s), base);
    slots.push_back(&texs[s]);
  }
  const std::vector<Filter> filters = built_filters(c);
  std::vector<TexRequest> reqs;
  for (int n = 0; n < 6000; ++n) {
    TexRequest r;
    r.slot = static_cast<unsigned>(rng() % texs.size());
    r.u = static_cast<int64_t>(rng() % (300u << c.texcoord_frac_bits)) - (100 << c.texcoord_frac_bits);
    r.v = static_cast<int64_t>(rng() % (300u << c.texcoord_frac_bits)) - (100 << c.texcoord_frac_bits);
    r.filter = filters[rng() % filters.size()];
    r.wrap_u = static_cast<Wrap>(rng() % 3);
    r.wrap_v = static_cast<Wrap>(rng() % 3);
    r.lod = static_cast<int32_t>(rng() % (10u << c.lod_frac_bits)) - (1 << c.lod_frac_bits);
    reqs.push_back(r);
  }
  const Check k = run_and_compare(h, c, slots, reqs, 300, 5);
  EXPECT_EQ(k.bad, 0u) << k.first;
  // The sample counter counts every result when built (CAPS.COUNTERS), and reads 0 otherwise.
  const bool counters = (h.reg_read(0x000) >> 7) & 1;
  EXPECT_EQ(counters, GetParam() == "full");
  EXPECT_EQ(h.reg_read(0x010), counters ? reqs.size() : 0u);
  h.reg_write(0x018, 1);
  EXPECT_EQ(h.reg_read(0x010), 0u);
}

// In `icebreaker` a descriptor read shares the descriptors' multiplexer with the requests
// (htx_tex_regs SharedDescMux): it waits in a clock in which a request is taken. Reads of every slot
// (and of one beyond the built slots, which reads 0) issued back to back while requests stream must
// all answer their descriptor, in `icebreaker` some must have waited (in `full`, with a multiplexer
// of their own, none), and every sample must still match the model.
TEST_P(TextureUnit, DescriptorReadsWhileSampling) {
  const ModelConfig& c = cfg();
  TextureHarness h(GetParam());
  std::mt19937 rng(31);
  const unsigned built_slots = (h.reg_read(0x000) >> 8) & 0xF;
  ASSERT_GE(built_slots, 2u);
  std::vector<Texture> texs;
  std::vector<const Texture*> slots;
  uint32_t base = 0;
  for (unsigned s = 0; s < built_slots; ++s) {
    const unsigned a = 3 + s % 3, b = 3 + (s + 1) % 3;
    std::vector<uint8_t> px(size_t{4} << (a + b));
    for (uint8_t& x : px) x = static_cast<uint8_t>(rng());
    texs.push_back(make_texture(s % 2 ? TexFormat::RGBA4444 : TexFormat::RGB565, a, b, px));
  }
  for (unsigned s = 0; s < built_slots; ++s) {
    base += h.upload(texs[s], s, base);
    slots.push_back(&texs[s]);
  }
  TexRunReads reads;
  std::vector<uint32_t> expected;
  for (unsigned s = 0; s <= built_slots && s < 8; ++s) {
    reads.offsets.push_back(0x100 + 4 * s);
    expected.push_back(h.reg_read(0x100 + 4 * s));
  }
  if (built_slots < 8) {
    EXPECT_EQ(expected.back(), 0u);  // a slot not built reads 0
  }
  const std::vector<Filter> filters = built_filters(c);
  std::vector<TexRequest> reqs;
  for (int n = 0; n < 1500; ++n) {
    TexRequest r;
    r.slot = static_cast<unsigned>(rng() % built_slots);
    r.u = static_cast<int64_t>(rng() % (200u << c.texcoord_frac_bits)) - (50 << c.texcoord_frac_bits);
    r.v = static_cast<int64_t>(rng() % (200u << c.texcoord_frac_bits)) - (50 << c.texcoord_frac_bits);
    r.filter = filters[rng() % filters.size()];
    r.wrap_u = static_cast<Wrap>(rng() % 3);
    r.wrap_v = static_cast<Wrap>(rng() % 3);
    reqs.push_back(r);
  }
  const Check k = run_and_compare(h, c, slots, reqs, 0, 1, &reads);
  EXPECT_EQ(k.bad, 0u) << k.first;
  ASSERT_GT(reads.values.size(), reqs.size());
  if (GetParam() == "icebreaker") {
    EXPECT_GT(reads.waited, 0u);
  } else {
    EXPECT_EQ(reads.waited, 0u);
  }
  for (size_t i = 0; i < reads.values.size(); ++i)
    ASSERT_EQ(reads.values[i], expected[i % expected.size()]) << "read " << i;
}

INSTANTIATE_TEST_SUITE_P(Configs, TextureUnit, ::testing::Values("full", "icebreaker"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

// LOD selection across a minified plane: the `floor` scene's per-pixel LOD inputs (the model's
// planes, RECIP_NR coordinates) through the unit's LOD stage and trilinear filter.
TEST(TextureLod, FloorSceneTrilinear) {
  const ModelConfig& c = model_config("full");
  TextureHarness h("full");
  const ScreenScene scene = prepare_screen_scene(make_builtin_scene("floor"), 160, 120);
  ASSERT_FALSE(scene.textures.empty());
  std::vector<const Texture*> slots;
  uint32_t base = 0;
  for (size_t s = 0; s < scene.textures.size() && s < 8; ++s) {
    base += h.upload(scene.textures[s], static_cast<unsigned>(s), base);
    slots.push_back(&scene.textures[s]);
  }
  const model::Log2Unit log2_unit(c.lod_log_index_bits, c.lod_frac_bits + 2);
  const unsigned tf = c.texcoord_frac_bits;
  std::vector<TexRequest> reqs;
  std::vector<int32_t> model_lods;
  model::SpanCoords span;
  for (const ScreenTri& tri : scene.tris) {
    if (!tri.state.textured || tri.state.texture >= 8) continue;
    TriState st = tri.state;
    st.filter = Filter::Trilinear;
    st.method = Method::RecipNr;
    fw::VertexIn in[3] = {to_vertex_in(tri.v[0]), to_vertex_in(tri.v[1]), to_vertex_in(tri.v[2])};
    fw::TriangleRecord rec;
    if (fw::encode_triangle(c.record_format(), in, &rec) != fw::kEncodeOk) continue;
    const Texture& tex = scene.textures[static_cast<size_t>(st.texture)];
    const model::TriangleUnit unit(rec, st, c, scene.width, scene.height, &log2_unit, level_count(tex) - 1);
    if (unit.empty()) continue;
    const model::i128 g[6] = {unit.uq_plane().gx, unit.uq_plane().gy, unit.vq_plane().gx,
                              unit.vq_plane().gy, unit.q_plane().gx,  unit.q_plane().gy};
    const int shift = model::lod_gradient_shift(g, c.lod_grad_bits);
    for (int y = unit.y_lo(); y <= unit.y_hi(); ++y) {
      int x0 = 0, x1 = -1;
      if (!unit.span(y, &x0, &x1)) continue;
      unit.span_coords(y, x0, x1, Method::RecipNr, &span);
      for (int x = x0; x <= x1; ++x) {
        const size_t k = static_cast<size_t>(x - x0);
        const int64_t px = 256 * int64_t{x} + 128, py = 256 * int64_t{y} + 128;
        TexRequest r;
        r.u = span.u[k] + (int64_t{rec.u_offset} << tf);
        r.v = span.v[k] + (int64_t{rec.v_offset} << tf);
        r.filter = Filter::Trilinear;
        r.wrap_u = st.wrap_u;
        r.wrap_v = st.wrap_v;
        r.slot = static_cast<unsigned>(st.texture);
        r.lod_direct = false;
        r.q = static_cast<uint64_t>(std::max<model::i128>(unit.q_plane().at(px, py), 1));
        for (int i = 0; i < 6; ++i) r.g[i] = static_cast<int64_t>(g[i] >> shift);
        r.grad_shift = static_cast<unsigned>(shift);
        r.lu = span.u[k];
        r.lv = span.v[k];
        reqs.push_back(r);
        model_lods.push_back(unit.lod_at(log2_unit, px, py, span.u[k], span.v[k]));
      }
    }
  }
  ASSERT_GT(reqs.size(), 1000u);
  // The inputs rebuilt here are the model's own: compute_lod on them equals lod_at.
  for (size_t i = 0; i < reqs.size(); ++i) {
    const Expected e = model_sample(*slots[reqs[i].slot], c, reqs[i]);
    const int32_t top = static_cast<int32_t>(level_count(*slots[reqs[i].slot]) - 1) << c.lod_frac_bits;
    ASSERT_EQ(e.lod, model_lods[i] == INT32_MIN ? 0 : std::clamp(model_lods[i], 0, top)) << i;
  }
  std::set<unsigned> levels;
  for (size_t i = 0; i < reqs.size(); ++i) levels.insert(model_sample(*slots[reqs[i].slot], c, reqs[i]).level);
  EXPECT_GE(levels.size(), 3u) << "the plane should be minified across several levels";
  const Check k = run_and_compare(h, c, slots, reqs, 100, 3);
  EXPECT_EQ(k.bad, 0u) << k.first;
}

// Random LOD inputs over the full widths (q, gradients, block shift, coordinates).
TEST(TextureLod, RandomInputs) {
  const ModelConfig& c = model_config("full");
  TextureHarness h("full");
  const Texture tex = gradient_texture(TexFormat::RGB565, 8);
  h.upload(tex, 0, 0);
  std::mt19937_64 rng(99);
  std::vector<TexRequest> reqs;
  auto sgn = [&](unsigned bits) {
    const unsigned b = 1 + rng() % bits;  // vary the magnitude
    return static_cast<int64_t>(rng() & ((uint64_t{1} << b) - 1)) - (int64_t{1} << (b - 1));
  };
  for (int n = 0; n < 5000; ++n) {
    TexRequest r;
    r.filter = Filter::Trilinear;
    r.lod_direct = false;
    r.q = 1 + (rng() & ((uint64_t{1} << (1 + rng() % 57)) - 1));
    for (int i = 0; i < 6; ++i) r.g[i] = n % 50 == 0 ? 0 : sgn(24);
    r.grad_shift = static_cast<unsigned>(rng() % 40);
    r.lu = sgn(32);
    r.lv = sgn(32);
    r.u = r.lu + static_cast<int64_t>(rng() % 4096) * 65536;
    r.v = r.lv;
    reqs.push_back(r);
  }
  const Check k = run_and_compare(h, c, {&tex}, reqs);
  EXPECT_EQ(k.bad, 0u) << k.first;
}

// Throughput with the output always taken: requests per clock over a long stream.
double measure(const std::string& config, Filter f, bool two_levels) {
  const ModelConfig& c = model_config(config);
  TextureHarness h(config);
  const Texture tex = gradient_texture(TexFormat::RGB565, 6);
  h.upload(tex, 0, 0);
  std::mt19937 rng(1);
  std::vector<TexRequest> reqs(4096);
  for (TexRequest& r : reqs) {
    r.u = rng() % (64u << c.texcoord_frac_bits);
    r.v = rng() % (64u << c.texcoord_frac_bits);
    r.filter = f;
    // Trilinear: a non-zero level weight on every request (two levels each), or whole levels.
    r.lod = static_cast<int32_t>((rng() % 5) << c.lod_frac_bits) + (two_levels ? 1 + static_cast<int32_t>(rng() % 255) : 0);
  }
  rtl::TexRunStats st;
  const std::vector<TexResult> got = h.run(reqs, 0, 1, &st);
  return static_cast<double>(got.size()) / static_cast<double>(st.cycles);
}

TEST(TextureThroughput, Measured) {
  const double full_bil = measure("full", Filter::Bilinear, false);
  const double full_near = measure("full", Filter::Nearest, false);
  const double full_tri2 = measure("full", Filter::Trilinear, true);
  const double full_tri1 = measure("full", Filter::Trilinear, false);
  const double ice_bil = measure("icebreaker", Filter::Bilinear, false);
  const double ice_near = measure("icebreaker", Filter::Nearest, false);
  std::printf("px_per_clk full: nearest %.4f bilinear %.4f trilinear (two levels) %.4f trilinear (whole levels) %.4f\n",
              full_near, full_bil, full_tri2, full_tri1);
  std::printf("px_per_clk icebreaker: nearest %.4f bilinear %.4f\n", ice_near, ice_bil);
  RecordProperty("full_bilinear_px_per_clk", std::to_string(full_bil));
  RecordProperty("full_trilinear_px_per_clk", std::to_string(full_tri2));
  RecordProperty("icebreaker_bilinear_px_per_clk", std::to_string(ice_bil));
  EXPECT_GE(full_bil, 0.95);
  EXPECT_GE(full_near, 0.95);
  EXPECT_GE(full_tri1, 0.95);
  EXPECT_GE(full_tri2, 0.45);
  // icebreaker has one axis unit for u and v (Lanes = 1): two clocks a request.
  EXPECT_GE(ice_near, 0.49);
  // icebreaker blends one product per clock on one DSP: 3 clocks a channel, 12 a bilinear texel.
  EXPECT_GE(ice_bil, 0.083);
}

}  // namespace
}  // namespace htx
