// Drives the Verilated raster subsystem (RasterSim) directly for the tests in this directory:
// encodes triangles exactly as render_model does (the encoder's rejects are not sent), pushes them
// with their state words, records the texture request port and reads the memories back. Unlike
// render_rtl it takes any built configuration name ("icebreaker_untextured" too).
#pragma once

#include <algorithm>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "htx/fw/vertex_record.h"
#include "htx/model/config.hpp"
#include "htx/model/perspective.hpp"
#include "htx/rtl/fifo_records.hpp"
#include "htx/rtl/raster_engine.hpp"
#include "htx/rtl/raster_sim.hpp"
#include "htx_regs.h"

namespace htx::raster_test {

inline uint32_t reg_off(size_t o) { return static_cast<uint32_t>(o); }
#define HTX_TEST_REG(name) ::htx::raster_test::reg_off(offsetof(HTX_RASTER_Type, name))

struct Tri {
  fw::TriangleRecord rec;
  TriState state;
  unsigned top_level = 0;  // DIVFREE: the texture's last mip level, sent in the state word
};

// Encodes a screen scene's triangles (AUTO resolved as render_model does); the encoder's rejects
// are not sent.
inline std::vector<Tri> encode(const ScreenScene& s, const ModelConfig& cfg) {
  std::vector<Tri> out;
  for (const ScreenTri& t : s.tris) {
    fw::VertexIn in[3];
    for (int i = 0; i < 3; ++i) {
      const ScreenVertex& v = t.v[i];
      in[i].x = v.x; in[i].y = v.y; in[i].z = v.z; in[i].w = v.w; in[i].u = v.u; in[i].v = v.v;
      in[i].r = v.r; in[i].g = v.g; in[i].b = v.b; in[i].a = v.a;
    }
    Tri tri;
    tri.state = t.state;
    if (tri.state.method == Method::Auto) tri.state.method = model::auto_method(t, cfg);
    if (fw::encode_triangle(cfg.record_format(), in, &tri.rec) != fw::kEncodeOk) continue;
    out.push_back(tri);
  }
  return out;
}

struct RtlResult {
  std::vector<rtl::TexRequest> requests;
  std::vector<uint16_t> color;
  std::vector<uint32_t> depth;
  uint64_t busy = 0, fragments = 0, pixels = 0, setup_busy = 0, triangles = 0, divfree_steps = 0;
};

// The configuration a built unit is of ("icebreaker_untextured" is `icebreaker`'s).
inline const ModelConfig& config_of_build(const std::string& name) {
  return model_config(name.rfind("icebreaker", 0) == 0 ? "icebreaker" : "full");
}

// How the unit takes triangles (CAPS.FW_SETUP: plane records set up for a w x h screen).
inline rtl::FifoRecords fifo_form(rtl::RasterSim& sim, const std::string& name, int w, int h) {
  return rtl::FifoRecords(config_of_build(name), sim.read_reg(HTX_TEST_REG(CAPS)), w, h);
}

// The FIFO stream of the triangles in the unit's form: each one's state word, then its packed
// record; or its plane record (a triangle that draws nothing is then not sent).
inline std::vector<uint32_t> words_of(const std::vector<Tri>& tris, const rtl::FifoRecords& form) {
  std::vector<uint32_t> words;
  for (const Tri& t : tris) form.append(&words, pack_state_word(t.state, t.state.method, t.top_level), t.rec);
  return words;
}

// Sets a w x h frame, clears it to clear_color / clear_depth and enables the unit.
inline void clear_frame(rtl::RasterSim& sim, int w, int h, uint16_t clear_color, uint32_t clear_depth) {
  sim.write_reg(HTX_TEST_REG(FB_SIZE), (static_cast<uint32_t>(w) << RASTER_FB_SIZE_WIDTH_Pos) |
                                           (static_cast<uint32_t>(h) << RASTER_FB_SIZE_HEIGHT_Pos));
  sim.write_reg(HTX_TEST_REG(FB_STRIDE), static_cast<uint32_t>(w));
  sim.write_reg(HTX_TEST_REG(CLEAR_COLOR), clear_color);
  sim.write_reg(HTX_TEST_REG(CLEAR_DEPTH), std::min<uint32_t>(clear_depth, 0xFFFFFFu));
  sim.write_reg(HTX_TEST_REG(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk | RASTER_CTRL_CLEAR_DEPTH_Msk);
  sim.wait_idle();
}

// Reads the w x h colour and depth memories into r (depth masked to z_bits).
inline void read_frame(rtl::RasterSim& sim, int w, int h, unsigned z_bits, RtlResult* r) {
  const uint32_t n = static_cast<uint32_t>(w) * static_cast<uint32_t>(h);
  r->color = sim.read_color(n);
  r->depth = sim.read_depth(n);
  for (uint32_t& z : r->depth) z &= (uint32_t{1} << z_bits) - 1;
}

// Pixels whose colour or depth differ from the model's frame; *first: the first of them.
inline uint64_t mismatch_pixels(const RtlResult& r, const Frame& m, size_t* first = nullptr) {
  uint64_t bad = 0;
  for (size_t i = 0; i < m.color.size(); ++i) {
    if (r.color[i] != m.color[i] || r.depth[i] != m.depth[i]) {
      if (!bad && first) *first = i;
      ++bad;
    }
  }
  return bad;
}

// Clears to clear_color / clear_depth, draws, records every request, reads both memories (depth
// masked to z_bits).
inline RtlResult draw(const std::string& name, const std::vector<Tri>& tris, int w, int h, uint16_t clear_color,
                      uint32_t clear_depth, unsigned z_bits) {
  rtl::RasterSim sim(name);
  const std::vector<uint32_t> words = words_of(tris, fifo_form(sim, name, w, h));
  clear_frame(sim, w, h, clear_color, clear_depth);
  sim.write_reg(HTX_TEST_REG(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_COUNTERS_RESET_Msk);
  RtlResult r;
  sim.record_requests(&r.requests);
  sim.push_words(words);
  sim.wait_idle(200'000'000);
  sim.record_requests(nullptr);
  EXPECT_EQ(sim.read_reg(HTX_TEST_REG(STATUS)) & RASTER_STATUS_ERR_STATE_Msk, 0u) << name;
  r.busy = sim.read_reg(HTX_TEST_REG(CNT_BUSY));
  r.fragments = sim.read_reg(HTX_TEST_REG(CNT_FRAGMENTS));
  r.pixels = sim.read_reg(HTX_TEST_REG(CNT_PIXELS));
  r.setup_busy = sim.read_reg(HTX_TEST_REG(CNT_SETUP_BUSY));
  r.triangles = sim.read_reg(HTX_TEST_REG(CNT_TRIANGLES));
  r.divfree_steps = sim.read_reg(HTX_TEST_REG(CNT_DIVFREE_STEPS));
  read_frame(sim, w, h, z_bits, &r);
  return r;
}

// Random untextured triangles (fixed seed): positions on and off the screen, tiny to huge, random
// colours, depth, depth functions, depth write, flat or Gouraud, and any method.
inline ScreenScene random_scene(uint32_t seed, int n, int width, int height) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ScreenScene s;
  s.name = "random";
  s.width = width;
  s.height = height;
  s.clear_color = static_cast<uint16_t>(rng());
  s.clear_depth = rng() % 3 == 0 ? static_cast<uint32_t>(rng()) : 0xFFFFFFFFu;
  for (int i = 0; i < n; ++i) {
    ScreenTri t;
    // Size class: tiny (sub-pixel to a few pixels), screen-sized, or far beyond the screen.
    const int cls = static_cast<int>(rng() % 8);
    // (Mid-size and huge triangles are kept rarer than tiny ones so the test stays quick.)
    const double spread = cls < 4 ? 4.0 : (cls < 7 ? 40.0 : (rng() % 4 == 0 ? 3000.0 : 40.0));
    const double cx = unit(rng) * (width + 40) - 20, cy = unit(rng) * (height + 40) - 20;
    for (ScreenVertex& v : t.v) {
      v.x = cx + (unit(rng) - 0.5) * spread;
      v.y = cy + (unit(rng) - 0.5) * spread;
      v.z = unit(rng) * 1.2 - 0.1;  // clamped to [0, 1] by the encoder
      v.w = 0.5 + unit(rng) * 4;
      v.r = unit(rng);
      v.g = unit(rng);
      v.b = unit(rng);
      v.a = unit(rng);
    }
    if (rng() % 16 == 0) t.v[2] = t.v[1];  // zero area
    t.state.textured = false;
    t.state.gouraud = rng() % 4 != 0;
    t.state.depth_func = static_cast<DepthFunc>(rng() % 6);
    t.state.depth_write = rng() % 4 != 0;
    t.state.method = static_cast<Method>(rng() % 5);  // AFFINE, SUBDIV, RECIP_LUT, RECIP_NR, DIVFREE
    s.tris.push_back(t);
  }
  return s;
}

}  // namespace htx::raster_test
