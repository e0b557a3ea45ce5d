// Robustness of the bit-accurate model (docs/robustness.md, "Model"): random ScreenScenes with
// NaN, infinite, negative and huge attributes, every method, filter and depth function, textured
// and not; and random vertex records anywhere in their documented field ranges through
// render_model_records. Each render returns a frame of exactly width x height pixels whose depths
// fit z_bits (no write outside the frame, no overflow of the model's datapath), or refuses the
// scene with std::invalid_argument. Triangles the encoder refuses draw nothing: the scene without
// them draws the same frame, bit for bit, with the same fragment and pixel counts. The model's
// sources are compiled into this test with the address and undefined-behaviour sanitizers
// (tests/fuzz/CMakeLists.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/model.hpp"
#include "htx/model/proc_textures.hpp"

namespace htx {
namespace {

double hostile(std::mt19937& rng, double lo, double hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (rng() % 12) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return (rng() & 1u) ? inf : -inf;
    case 2: return (rng() & 1u) ? 1e300 : -1e300;
    case 3: return std::numeric_limits<double>::denorm_min();
    case 4: return -lo - hi;
    default: return std::uniform_real_distribution<double>(lo, hi)(rng);
  }
}

// Whether the vertex-record encoder takes the triangle (the inputs built here from the screen
// vertices, not by the model's own conversion).
bool encoder_takes(const ScreenTri& t, const ModelConfig& cfg) {
  fw::VertexIn in[3];
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex& v = t.v[static_cast<size_t>(i)];
    in[i].x = v.x;
    in[i].y = v.y;
    in[i].z = v.z;
    in[i].w = v.w;
    in[i].u = v.u;
    in[i].v = v.v;
    in[i].r = v.r;
    in[i].g = v.g;
    in[i].b = v.b;
    in[i].a = v.a;
  }
  fw::TriangleRecord r;
  return fw::encode_triangle(cfg.record_format(), in, &r) == fw::kEncodeOk;
}

void expect_frame_shape(const Frame& f, int w, int h, const ModelConfig& cfg, const std::string& what) {
  ASSERT_EQ(f.width, w) << what;
  ASSERT_EQ(f.height, h) << what;
  ASSERT_EQ(f.color.size(), static_cast<size_t>(w) * static_cast<size_t>(h)) << what;
  ASSERT_EQ(f.depth.size(), static_cast<size_t>(w) * static_cast<size_t>(h)) << what;
  const uint32_t zmax = (uint32_t{1} << cfg.z_bits) - 1;
  for (uint32_t z : f.depth) ASSERT_LE(z, zmax) << what;
  EXPECT_LE(f.counters.pixels_written, f.counters.fragments) << what;
}

TEST(ModelFuzz, HostileScreenScenes) {
  std::mt19937 rng(41);
  for (const char* name : {"full", "icebreaker"}) {
    const ModelConfig cfg = model_config(name);
    // Scenes with refused triangles, and those where the refused triangles would have changed the
    // frame had they been drawn anyway (the same triangles with every coordinate clamped on screen
    // and w made positive: see below), so that the comparison is known to see a drawn one.
    int scenes_with_refused = 0, refused_that_would_show = 0;
    for (int iter = 0; iter < 400; ++iter) {
      const std::string what = std::string(name) + " scene " + std::to_string(iter);
      ScreenScene s;
      s.width = 1 + static_cast<int>(rng() % 48);
      s.height = 1 + static_cast<int>(rng() % 40);
      s.textures.push_back(checkerboard_texture(TexFormat::RGB565, 3 + rng() % 4, 1, {255, 0, 0, 255}, {0, 0, 255, 255}));
      s.clear_color = static_cast<uint16_t>(rng());
      s.clear_depth = rng();
      for (int t = 0; t < 6; ++t) {
        ScreenTri tri;
        for (auto& v : tri.v) {
          const bool wild = rng() % 3 == 0;
          v.x = wild ? hostile(rng, -1e5, 1e5) : std::uniform_real_distribution<double>(-20, 70)(rng);
          v.y = wild ? hostile(rng, -1e5, 1e5) : std::uniform_real_distribution<double>(-20, 60)(rng);
          v.z = rng() % 4 ? std::uniform_real_distribution<double>(0, 1)(rng) : hostile(rng, -2, 2);
          v.w = rng() % 4 ? std::uniform_real_distribution<double>(0.05, 50)(rng) : hostile(rng, -1, 1e6);
          v.u = rng() % 4 ? std::uniform_real_distribution<double>(-64, 64)(rng) : hostile(rng, -1e9, 1e9);
          v.v = rng() % 4 ? std::uniform_real_distribution<double>(-64, 64)(rng) : hostile(rng, -1e5, 1e5);
          v.r = hostile(rng, -0.5, 1.5);
          v.g = hostile(rng, 0, 1);
          v.b = std::uniform_real_distribution<double>(0, 1)(rng);
          v.a = hostile(rng, 0, 1);
        }
        TriState& st = tri.state;
        st.method = static_cast<Method>(rng() % 7);  // Auto included; Quadratic is built in the model
        st.subdiv_n = 2 + rng() % 63;
        st.filter = static_cast<Filter>(rng() % (cfg.name == "full" ? 3 : 2));
        st.wrap_u = static_cast<Wrap>(rng() % 3);
        st.wrap_v = static_cast<Wrap>(rng() % 3);
        st.depth_func = static_cast<DepthFunc>(rng() % 6);
        st.depth_write = rng() & 1u;
        st.textured = rng() & 1u;
        st.gouraud = rng() & 1u;
        st.combine = static_cast<Combine>(rng() % 2);
        st.texture = 0;
        s.tris.push_back(tri);
      }
      try {
        const Frame f = render_model(s, cfg);
        expect_frame_shape(f, s.width, s.height, cfg, what);
        // The refused triangles draw nothing: the frame without them is the same.
        ScreenScene kept = s, tamed = s;
        kept.tris.clear();
        for (ScreenTri& t : tamed.tris) {
          if (encoder_takes(t, cfg)) {
            kept.tris.push_back(t);
            continue;
          }
          for (ScreenVertex& v : t.v) {
            v.x = std::isfinite(v.x) ? std::clamp(v.x, -8.0, s.width + 8.0) : 0.0;
            v.y = std::isfinite(v.y) ? std::clamp(v.y, -8.0, s.height + 8.0) : 0.0;
            v.z = std::isfinite(v.z) ? std::clamp(v.z, 0.0, 1.0) : 0.5;
            v.w = std::isfinite(v.w) && v.w > 0.01 ? std::min(v.w, 1e3) : 1.0;
            v.u = std::isfinite(v.u) ? std::clamp(v.u, -64.0, 64.0) : 0.0;
            v.v = std::isfinite(v.v) ? std::clamp(v.v, -64.0, 64.0) : 0.0;
          }
        }
        if (kept.tris.size() < s.tris.size()) {
          ++scenes_with_refused;
          const Frame g = render_model(kept, cfg);
          ASSERT_EQ(g.color.size(), f.color.size()) << what;
          size_t differing = 0;
          for (size_t i = 0; i < f.color.size(); ++i) differing += g.color[i] != f.color[i] || g.depth[i] != f.depth[i];
          EXPECT_EQ(differing, 0u) << what << ": the refused triangles changed the frame";
          EXPECT_EQ(g.counters.fragments, f.counters.fragments) << what;
          EXPECT_EQ(g.counters.pixels_written, f.counters.pixels_written) << what;
          const Frame h = render_model(tamed, cfg);
          size_t shown = 0;
          for (size_t i = 0; i < f.color.size(); ++i) shown += h.color[i] != f.color[i] || h.depth[i] != f.depth[i];
          refused_that_would_show += shown > 0;
        }
      } catch (const std::invalid_argument& e) {
        ADD_FAILURE() << what << ": a scene inside the documented limits was refused: " << e.what();
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": " << e.what();
      }
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("%s: %d scenes with refused triangles, %d where they would have shown\n", name, scenes_with_refused,
                refused_that_would_show);
    EXPECT_GT(scenes_with_refused, 300) << name;
    EXPECT_GT(refused_that_would_show, 250) << name;
  }
}

// Scene-level errors are refused with std::invalid_argument naming the problem.
TEST(ModelFuzz, SceneLevelErrorsAreRefused) {
  const ModelConfig cfg = model_config("icebreaker");
  ScreenScene s;
  s.tris.resize(1);
  s.tris[0].v[1].x = 10;
  s.tris[0].v[2].y = 10;
  for (auto [w, h] : {std::pair{0, 10}, std::pair{10, 0}, std::pair{-3, 5}, std::pair{4097, 1}, std::pair{1, 5000}}) {
    s.width = w;
    s.height = h;
    EXPECT_THROW(render_model(s, cfg), std::invalid_argument) << w << "x" << h;
  }
  s.width = s.height = 16;
  s.tris[0].state.textured = true;
  s.tris[0].state.texture = 3;  // missing
  EXPECT_THROW(render_model(s, cfg), std::invalid_argument);
  s.tris[0].state.texture = 0;
  s.tris[0].state.filter = Filter::Trilinear;  // not built in icebreaker
  s.textures.push_back(checkerboard_texture(TexFormat::RGB565, 3, 1, {0, 0, 0, 255}, {255, 255, 255, 255}));
  EXPECT_THROW(render_model(s, cfg), std::invalid_argument);
  s.tris[0].state.filter = Filter::Nearest;
  s.tris[0].state.method = Method::Subdiv;
  s.tris[0].state.subdiv_n = 1;
  EXPECT_THROW(render_model(s, cfg), std::invalid_argument);
}

// Records anywhere in their documented ranges (what a correct encoder may produce): coordinates
// over the whole signed XW-bit range, q from 1 to 2^q_bits - 1 with the largest in the top half,
// uq/vq over their whole range, any offsets below 2^30, any q_exp, all methods and filters.
TEST(ModelFuzz, RecordsOverTheirWholeRange) {
  std::mt19937 rng(42);
  for (const char* name : {"full", "icebreaker"}) {
    const ModelConfig cfg = model_config(name);
    const fw::RecordFormat f = cfg.record_format();
    auto sbits = [&](unsigned n) -> int64_t {
      const uint64_t r = (static_cast<uint64_t>(rng()) << 32) | rng();
      return static_cast<int64_t>(r << (64 - n)) >> (64 - n);
    };
    for (int iter = 0; iter < 300; ++iter) {
      const std::string what = std::string(name) + " records " + std::to_string(iter);
      RecordScene s;
      s.width = 1 + static_cast<int>(rng() % 40);
      s.height = 1 + static_cast<int>(rng() % 32);
      s.textures.push_back(checkerboard_texture(TexFormat::RGB565, 3 + rng() % 3, 1, {9, 99, 199, 255}, {200, 0, 50, 255}));
      for (int t = 0; t < 5; ++t) {
        RecordTriangle rt;
        fw::TriangleRecord& r = rt.record;
        r.u_offset = static_cast<int32_t>(sbits(31));
        r.v_offset = static_cast<int32_t>(sbits(31));
        r.q_exp = static_cast<int32_t>(sbits(8));
        for (auto& v : r.v) {
          const bool near = rng() % 2;
          v.x = near ? static_cast<int32_t>(rng() % (s.width * 512)) - s.width * 128 : static_cast<int32_t>(sbits(f.xy_int_bits + 8));
          v.y = near ? static_cast<int32_t>(rng() % (s.height * 512)) - s.height * 128 : static_cast<int32_t>(sbits(f.xy_int_bits + 8));
          v.z = static_cast<uint32_t>(rng() & ((1u << f.z_bits) - 1u));
          v.q = 1 + static_cast<uint32_t>(((static_cast<uint64_t>(rng()) << 32 | rng()) % ((uint64_t{1} << f.q_bits) - 1)));
          v.uq = rng() % 2 ? sbits(f.q_bits + f.uv_int_bits) : static_cast<int64_t>(rng() % 4096) * v.q / 64;
          v.vq = rng() % 2 ? sbits(f.q_bits + f.uv_int_bits) : static_cast<int64_t>(rng() % 4096) * v.q / 64;
          v.rgba = rng();
        }
        r.v[rng() % 3].q |= uint32_t{1} << (f.q_bits - 1);  // the largest q is normalised
        TriState& st = rt.state;
        st.method = static_cast<Method>(rng() % 6);
        st.subdiv_n = 2 + rng() % 63;
        st.filter = static_cast<Filter>(rng() % (cfg.name == "full" ? 3 : 2));
        st.depth_func = static_cast<DepthFunc>(rng() % 6);
        st.depth_write = rng() & 1u;
        st.textured = rng() & 1u;
        st.gouraud = rng() & 1u;
        st.texture = 0;
        s.tris.push_back(rt);
      }
      try {
        const Frame fr = render_model_records(s, cfg);
        expect_frame_shape(fr, s.width, s.height, cfg, what);
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": " << e.what();
      }
      if (::testing::Test::HasFailure()) return;
    }
  }
}

}  // namespace
}  // namespace htx
