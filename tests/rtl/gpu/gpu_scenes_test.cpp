// The GPU (raster + texture unit) against the model, bit for bit: framebuffer and depth buffer of
// every built-in scene rendered textured, in both configurations. Every value of each axis (filter,
// wrap mode per axis, texture format, perspective method) that the configuration builds appears on
// every scene; the combinations rotate with the scene index so that 3 renders per scene cover them
// (the full product, about 400 renders per method, is a benchmark, not a test: docs/gpu.md).
// CNT_DIVFREE_STEPS must equal the model's divfree_steps_total on every case. `icebreaker_board`
// is `icebreaker` with the board's methods only, which render_rtl draws on the GPU built with just
// AFFINE and RECIP_LUT (the synthesised design: no LOD gradients, DIVFREE left out).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "htx/model/metrics.hpp"
#include "htx/model/geometry.hpp"
#include "htx/model/model.hpp"
#include "htx/model/names.hpp"
#include "htx/model/scenes.hpp"
#include "htx/model/texture.hpp"
#include "htx/rtl/raster_engine.hpp"

namespace htx {
namespace {

struct Case {
  std::string config;
  std::string scene;
  Filter filter;
  Wrap wrap_u, wrap_v;
  TexFormat format;
  Method method;
  Combine combine;
};

std::string case_name(const Case& c) {
  std::string n = c.config + "_" + c.scene + "_" + std::string(filter_name(c.filter)) + "_" +
                  std::string(wrap_name(c.wrap_u)) + "_" + std::string(wrap_name(c.wrap_v)) + "_" +
                  std::string(tex_format_name(c.format)) + "_" + method_name(c.method, 8) +
                  (c.combine == Combine::Replace ? "_replace" : "_modulate");
  for (char& ch : n)
    if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

// The same texture in another format: level 0 decoded to 8-bit channels, re-encoded, chain rebuilt.
Texture convert(const Texture& t, TexFormat format) {
  if (t.format == format) return t;
  const unsigned w = 1u << t.log2_width, h = 1u << t.log2_height;
  std::vector<uint8_t> px(4 * w * h);
  for (unsigned j = 0; j < h; ++j)
    for (unsigned i = 0; i < w; ++i) {
      const Rgba8 c = decode_texel(t.format, t.levels[0][j * w + i]);
      // A varying alpha, so RGBA formats carry information in it too.
      const uint8_t a = static_cast<uint8_t>(255 - ((i * 7 + j * 13) & 0x7F));
      uint8_t* p = &px[4 * (j * w + i)];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
      p[3] = a;
    }
  return make_texture(format, t.log2_width, t.log2_height, px);
}

ModelConfig case_config(const std::string& name) {
  return name == "icebreaker_board" ? rtl_board_config() : rtl_config(name);
}

class GpuScenes : public ::testing::TestWithParam<Case> {};

TEST_P(GpuScenes, MatchesModelBitForBit) {
  const Case& c = GetParam();
  constexpr int kW = 160, kH = 120;
  ScreenScene screen = prepare_screen_scene(make_builtin_scene(c.scene), kW, kH);
  screen.clear_color = 0x1234;
  for (Texture& t : screen.textures) t = convert(t, c.format);
  for (ScreenTri& t : screen.tris) {
    t.state.filter = c.filter;
    t.state.wrap_u = c.wrap_u;
    t.state.wrap_v = c.wrap_v;
    t.state.method = c.method;
    t.state.subdiv_n = 8;
    // Replace shows the texel alone; modulate multiplies in the Gouraud colour.
    if (t.state.textured) t.state.combine = c.combine;
  }
  const ModelConfig cfg = case_config(c.config);
  const Frame model = render_model(screen, cfg);
  RtlStats stats;
  const Frame rtl = render_rtl(screen, cfg, &stats);
  ASSERT_EQ(rtl.color.size(), model.color.size());
  const FrameMismatch mismatch = exact_mismatch(rtl, model);
  EXPECT_EQ(mismatch.pixels, 0u) << "first mismatch (rtl against model) at " << mismatch.first;
  EXPECT_EQ(stats.covered_pixels, model.counters.fragments);
  EXPECT_EQ(stats.pixels_written, model.counters.pixels_written);
  EXPECT_EQ(stats.triangles, stats.triangles_sent);
  EXPECT_EQ(stats.divfree_steps, model.counters.divfree_steps_total) << "CNT_DIVFREE_STEPS";
}

template <class E>
std::vector<E> built(uint32_t mask, unsigned count) {
  std::vector<E> out;
  for (unsigned i = 0; i < count; ++i)
    if ((mask >> i) & 1u) out.push_back(static_cast<E>(i));
  return out;
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  const std::vector<Wrap> wraps = {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror};
  for (const char* name : {"full", "icebreaker", "icebreaker_board"}) {
    const ModelConfig cfg = case_config(name);
    const std::vector<Filter> filters = built<Filter>(cfg.filters, 3);
    const std::vector<TexFormat> formats = built<TexFormat>(cfg.formats, 3);
    const std::vector<Method> methods = built<Method>(cfg.methods, static_cast<unsigned>(Method::Auto));
    unsigned k = 0;
    for (const SceneInfo& s : builtin_scenes()) {
      for (size_t w = 0; w < wraps.size(); ++w, ++k) {
        Case c;
        c.config = name;
        c.scene = s.name;
        c.wrap_u = wraps[w];
        c.wrap_v = wraps[(w + k / 3) % wraps.size()];
        c.filter = filters[k % filters.size()];
        c.format = formats[(k / filters.size()) % formats.size()];
        c.method = methods[(k + k / (filters.size() * methods.size())) % methods.size()];
        c.combine = (k % 2) ? Combine::Replace : Combine::Modulate;
        cases.push_back(c);
      }
    }
  }
  return cases;
}

// The rotation must reach every value of every axis the configuration builds, on both wrap axes.
TEST(GpuScenesCases, CoverEveryBuiltValueOfEachAxis) {
  const std::vector<Case> cases = all_cases();
  for (const char* name : {"full", "icebreaker", "icebreaker_board"}) {
    const ModelConfig cfg = case_config(name);
    uint32_t filters = 0, formats = 0, methods = 0, wraps_u = 0, wraps_v = 0, combines = 0;
    size_t scenes = 0;
    for (const Case& c : cases) {
      if (c.config != name) continue;
      filters |= 1u << static_cast<unsigned>(c.filter);
      formats |= 1u << static_cast<unsigned>(c.format);
      methods |= 1u << static_cast<unsigned>(c.method);
      wraps_u |= 1u << static_cast<unsigned>(c.wrap_u);
      wraps_v |= 1u << static_cast<unsigned>(c.wrap_v);
      combines |= 1u << static_cast<unsigned>(c.combine);
      ++scenes;
    }
    EXPECT_EQ(filters, cfg.filters) << name;
    EXPECT_EQ(formats, cfg.formats) << name;
    EXPECT_EQ(methods, cfg.methods) << name;
    EXPECT_EQ(wraps_u, 7u) << name;
    EXPECT_EQ(wraps_v, 7u) << name;
    EXPECT_EQ(combines, 3u) << name;
    EXPECT_EQ(scenes, 3 * builtin_scenes().size()) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(All, GpuScenes, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& i) { return case_name(i.param); });

// DIVFREE on every built-in scene in both configurations (the rotation above reaches about half of
// them with it): every built filter in turn, the wraps and formats rotating; frame, depth and
// CNT_DIVFREE_STEPS equal to the model's.
std::vector<Case> divfree_cases() {
  std::vector<Case> cases;
  const Wrap wraps[] = {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror};
  for (const char* name : {"full", "icebreaker"}) {
    const std::vector<TexFormat> formats = built<TexFormat>(rtl_config(name).formats, 3);
    const std::vector<Filter> filters = built<Filter>(rtl_config(name).filters, 3);
    unsigned k = 0;
    for (const SceneInfo& s : builtin_scenes()) {
      Case c;
      c.config = name;
      c.scene = s.name;
      c.filter = filters[k % filters.size()];
      c.wrap_u = wraps[k % 3];
      c.wrap_v = wraps[(k + 1) % 3];
      c.format = formats[k % formats.size()];
      c.method = Method::DivFree;
      c.combine = (k % 2) ? Combine::Replace : Combine::Modulate;
      cases.push_back(c);
      ++k;
    }
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Divfree, GpuScenes, ::testing::ValuesIn(divfree_cases()),
                         [](const ::testing::TestParamInfo<Case>& i) { return case_name(i.param); });

}  // namespace
}  // namespace htx
