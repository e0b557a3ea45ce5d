// Robustness of the raster RTL (docs/robustness.md, "Raster unit"): random and corrupted FIFO word
// streams (random words, random state words, truncated triangles, records at the extremes of the
// coordinate range) in both configurations, each in its unit's form: vertex records (`full`) or
// plane records (`icebreaker`, CAPS.FW_SETUP, whose random records also get valid boxes around
// random planes and flags). Invariants checked on every stream:
//   - bounded time: the unit is idle again within a bound proportional to the on-screen area per
//     triangle taken plus a constant (never a hang);
//   - no write outside the frame: the stride gap, the rows below the frame and the top of both
//     memories (where a negative address would wrap) keep their sentinels;
//   - ABORT always returns the unit to idle with an empty FIFO, and a clean frame afterwards equals
//     the model;
//   - well-formed records at the extremes of the range render exactly as the model renders them.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "htx/fw/plane_record.h"
#include "htx/fw/vertex_record.h"
#include "htx/model/model.hpp"
#include "htx/rtl/fifo_records.hpp"
#include "htx/rtl/raster_engine.hpp"
#include "htx/rtl/raster_sim.hpp"
#include "htx_regs.h"

namespace htx {
namespace {

constexpr uint32_t reg(size_t offset) { return static_cast<uint32_t>(offset); }
#define R(name) reg(offsetof(HTX_RASTER_Type, name))

constexpr uint32_t kColorBase = 0x30000000u;
constexpr uint32_t kDepthBase = 0x30100000u;
constexpr uint32_t kGroupWords = 1 + fw::kTriangleWords;  // state word + record
constexpr uint16_t kColorSentinel = 0xA5C3;
constexpr uint32_t kDepthSentinel = 0x3C96u;  // fits the depth memory of both configurations (16 and 24 bits)

struct FbLayout {
  uint32_t width, height, stride;
};

uint32_t bits(std::mt19937& rng, unsigned n) { return n >= 32 ? rng() : rng() & ((1u << n) - 1u); }

// Clears the frame and puts sentinels everywhere the unit must not write: the stride gap of every
// row, two rows below the frame, and the last two rows' worth of pixels at the top of the memory.
void setup_frame(rtl::RasterSim& sim, const FbLayout& f, uint16_t clear_color) {
  sim.write_reg(R(FB_SIZE), f.width | (f.height << RASTER_FB_SIZE_HEIGHT_Pos));
  sim.write_reg(R(FB_STRIDE), f.stride);
  sim.write_reg(R(CLEAR_COLOR), clear_color);
  sim.write_reg(R(CLEAR_DEPTH), 0xFFFFFFu);
  sim.write_reg(R(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk | RASTER_CTRL_CLEAR_DEPTH_Msk);
  sim.wait_idle(1'000'000);
  auto guard = [&](uint32_t p) {
    const uint32_t be = (p & 1u) ? 0xCu : 0x3u;
    ASSERT_FALSE(sim.mem_write(kColorBase + (p >> 1) * 4u, uint32_t{kColorSentinel} * 0x10001u, static_cast<uint8_t>(be)));
    ASSERT_FALSE(sim.mem_write(kDepthBase + p * 4u, kDepthSentinel));
  };
  for (uint32_t y = 0; y < f.height; ++y)
    for (uint32_t x = f.width; x < f.stride; ++x) guard(y * f.stride + x);
  for (uint32_t p = f.height * f.stride; p < (f.height + 2) * f.stride; ++p) guard(p);
  for (uint32_t p = rtl::RasterSim::kFbPixels - 2 * f.stride; p < rtl::RasterSim::kFbPixels; ++p) guard(p);
  sim.write_reg(R(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_COUNTERS_RESET_Msk);
}

// Counts sentinel pixels that changed.
uint32_t count_outside_writes(rtl::RasterSim& sim, const FbLayout& f) {
  const uint32_t n = (f.height + 2) * f.stride;
  const std::vector<uint16_t> c = sim.read_color(n);
  const std::vector<uint32_t> z = sim.read_depth(n);
  uint32_t bad = 0;
  for (uint32_t p = 0; p < n; ++p) {
    const bool inside = p < f.height * f.stride && p % f.stride < f.width;
    if (!inside) bad += (c[p] != kColorSentinel) + ((z[p] & 0xFFFFFFu) != kDepthSentinel);
  }
  for (uint32_t p = rtl::RasterSim::kFbPixels - 2 * f.stride; p < rtl::RasterSim::kFbPixels; ++p) {
    uint32_t cw = 0, zw = 0;
    EXPECT_FALSE(sim.mem_read(kColorBase + (p >> 1) * 4u, &cw));
    EXPECT_FALSE(sim.mem_read(kDepthBase + p * 4u, &zw));
    bad += static_cast<uint16_t>((p & 1u) ? cw >> 16 : cw) != kColorSentinel;
    bad += (zw & 0xFFFFFFu) != kDepthSentinel;
  }
  return bad;
}

// Setup clocks allowed per triangle. `full` sets up in hardware in under 400. `icebreaker` reads
// plane records, two clocks a word (the words themselves are bounded separately).
uint64_t setup_allowance(const std::string& config) { return config == "icebreaker" ? 200 : 400; }

// Clocks a traversal step may take at most. `full` steps a pixel a clock, its pipelined divider
// keeps up and DIVFREE's walk holds it a few clocks (4). `icebreaker` steps its three edges and
// seven planes one a clock (10), and a divided pixel may hold it longer: the serial normaliser (up
// to 41 clocks), the Newton steps and the numerators' products (3 or 4 clocks each) (96).
uint64_t step_clocks(const std::string& config) { return config == "icebreaker" ? 96 : 4; }

// Clocks allowed for `groups` triangles: each may cover the whole frame (a row costs its span plus
// the distance its start moved, at most 2·width + 2 steps), plus setup and the words themselves.
uint64_t cycle_bound(uint64_t groups, const FbLayout& f, uint64_t setup_clocks, uint64_t step) {
  return groups * ((2ull * f.width * f.height + 4ull * f.height) * step + setup_clocks) + 5000;
}

// A FIFO stream under construction in the unit's form, and the triangles the unit will count
// taking (CNT_TRIANGLES). Plane records are followed word by word through htx_raster_planes_in's
// framing (state word, six header words, DIVFREE's 18, pairs to the one marked LAST), so that
// close() can end a record wherever random words left it.
class Stream {
 public:
  Stream(const ModelConfig& cfg, rtl::RasterSim& sim, const FbLayout& f)
      : form_(cfg, sim.read_reg(R(CAPS)), static_cast<int>(f.width), static_cast<int>(f.height)) {}

  bool planes() const { return form_.fw_setup(); }
  const std::vector<uint32_t>& words() const { return words_; }
  uint64_t groups() const { return planes() ? groups_ : words_.size() / kGroupWords; }

  void word(uint32_t w) {
    words_.push_back(w);
    if (!planes()) return;
    if (!in_rec_) {
      in_rec_ = true;
      ++groups_;
      divfree_ = (w & RASTER_STATE_METHOD_Msk) >> RASTER_STATE_METHOD_Pos == 4;
      count_ = 1;
      phase_ = kHead;
    } else if (phase_ == kHead) {
      if (++count_ == fw::kPlaneHeaderWords) {
        phase_ = divfree_ ? kSide : kPairs;
        count_ = 0;
        high_ = false;
      }
    } else if (phase_ == kSide) {
      if (++count_ == fw::kPlaneSideWords) phase_ = kPairs;
    } else {
      if (high_ && (w & fw::kPlaneLastBit)) in_rec_ = false;
      high_ = !high_;
    }
  }
  // In the middle of a plane record's header: the word index (else 0).
  uint32_t header_word() const { return in_rec_ && phase_ == kHead ? count_ : 0; }

  // A well-formed triangle (plane form: set up for the frame; one that draws nothing is not sent).
  void record(uint32_t state, const fw::TriangleRecord& r) {
    std::vector<uint32_t> w;
    form_.append(&w, state, r);
    for (uint32_t x : w) word(x);
  }

  // Vertex form: pads to whole groups. Plane form: ends the record under way.
  void close(std::mt19937& rng) {
    if (!planes()) {
      while (words_.size() % kGroupWords) words_.push_back(rng());
      return;
    }
    while (in_rec_) word(phase_ == kPairs && high_ ? (rng() | fw::kPlaneLastBit) : rng());
  }

 private:
  enum Phase { kHead, kSide, kPairs };
  rtl::FifoRecords form_;
  std::vector<uint32_t> words_;
  uint64_t groups_ = 0;
  bool in_rec_ = false, divfree_ = false, high_ = false;
  uint32_t count_ = 0;
  Phase phase_ = kHead;
};

// Pushes the stream, then waits for idle within the bound; returns false (with a failure) on a hang.
bool run_bounded(rtl::RasterSim& sim, const Stream& stream, const FbLayout& f, const std::string& config,
                 const std::string& what) {
  const std::vector<uint32_t>& words = stream.words();
  const uint64_t start = sim.cycles();
  const uint64_t bound =
      cycle_bound(stream.groups() + 1, f, setup_allowance(config), step_clocks(config)) + 2 * words.size();
  sim.push_words(words);
  const uint64_t used = sim.cycles() - start;
  if (used > bound) {
    ADD_FAILURE() << what << ": pushing " << words.size() << " words took " << used << " clocks, bound " << bound;
    return false;
  }
  try {
    sim.wait_idle(bound - used);
  } catch (const std::runtime_error& e) {
    ADD_FAILURE() << what << ": not idle within " << bound << " clocks of the first word (" << e.what() << ")";
    return false;
  }
  const uint32_t st = sim.read_reg(R(STATUS));
  EXPECT_TRUE(st & RASTER_STATUS_FIFO_EMPTY_Msk) << what;
  return true;
}

// A random untextured state word the unit builds (depth functions 0..5), or any 32-bit word.
uint32_t state_word(std::mt19937& rng, bool valid) {
  if (!valid) return rng();
  TriState s;
  s.textured = false;
  s.depth_func = static_cast<DepthFunc>(rng() % 6);
  s.depth_write = rng() & 1u;
  s.gouraud = rng() & 1u;
  s.method = static_cast<Method>(rng() % 5);
  s.subdiv_n = 2 + rng() % 63;
  return pack_state_word(s, s.method);
}

// A well-formed record with coordinates anywhere in the signed XW-bit range: near the frame, far
// off it, or at the very ends of the range (huge, sliver and degenerate triangles all occur).
fw::TriangleRecord extreme_record(std::mt19937& rng, const ModelConfig& cfg, const FbLayout& f) {
  const int32_t xy_max = (int32_t{1} << (cfg.xy_int_bits + 7)) - 1;  // 2^(XW-1) - 1 subpixels
  auto coord = [&](uint32_t extent) -> int32_t {
    switch (rng() % 6) {
      case 0: return (rng() & 1u) ? xy_max : -xy_max - 1;                       // range ends
      case 1: return static_cast<int32_t>(bits(rng, cfg.xy_int_bits + 8) << (24 - cfg.xy_int_bits)) >>
                     (24 - cfg.xy_int_bits);                                   // anywhere in range
      case 2: return static_cast<int32_t>(rng() % (extent * 256 + 1));          // on screen
      default: return static_cast<int32_t>(rng() % (extent * 768)) - static_cast<int32_t>(extent * 256);
    }
  };
  fw::TriangleRecord r;
  r.q_exp = 0;
  for (int i = 0; i < 3; ++i) {
    fw::VertexRecord& v = r.v[i];
    v.x = coord(f.width);
    v.y = coord(f.height);
    v.z = bits(rng, cfg.z_bits);
    v.q = (1u << (cfg.q_bits - 1)) | bits(rng, cfg.q_bits - 1);
    v.rgba = rng();
  }
  if (rng() % 4 == 0) r.v[2] = r.v[rng() % 2];  // a repeated vertex: zero area
  return r;
}

// A clean frame of ordinary triangles through the encoder: must equal the model exactly.
void expect_clean_frame(rtl::RasterSim& sim, std::mt19937& rng, const ModelConfig& cfg, const std::string& what) {
  ScreenScene s;
  s.width = 40;
  s.height = 30;
  s.clear_color = static_cast<uint16_t>(rng());
  const FbLayout f{40, 30, 40};
  Stream words(cfg, sim, f);
  for (int t = 0; t < 6; ++t) {
    ScreenTri tri;
    std::uniform_real_distribution<double> px(-10, 50), c(0, 1);
    for (auto& v : tri.v) {
      v.x = px(rng);
      v.y = px(rng);
      v.z = c(rng);
      v.r = c(rng);
      v.g = c(rng);
      v.b = c(rng);
    }
    tri.state.textured = false;
    tri.state.depth_func = static_cast<DepthFunc>(1 + rng() % 2);
    tri.state.gouraud = rng() & 1u;
    fw::VertexIn in[3];
    for (int i = 0; i < 3; ++i) {
      in[i].x = tri.v[i].x;
      in[i].y = tri.v[i].y;
      in[i].z = tri.v[i].z;
      in[i].r = tri.v[i].r;
      in[i].g = tri.v[i].g;
      in[i].b = tri.v[i].b;
    }
    fw::TriangleRecord rec;
    ASSERT_EQ(fw::encode_triangle(cfg.record_format(), in, &rec), fw::kEncodeOk);
    words.record(pack_state_word(tri.state, tri.state.method), rec);
    s.tris.push_back(tri);
  }
  setup_frame(sim, f, s.clear_color);
  ASSERT_TRUE(run_bounded(sim, words, f, cfg.name, what + " clean frame"));
  const htx::Frame m = render_model(s, cfg);
  const std::vector<uint16_t> c = sim.read_color(40 * 30);
  const std::vector<uint32_t> z = sim.read_depth(40 * 30);
  uint32_t bad = 0;
  for (uint32_t i = 0; i < 40 * 30; ++i) bad += (c[i] != m.color[i]) || ((z[i] & 0xFFFFFFu) != m.depth[i]);
  EXPECT_EQ(bad, 0u) << what << ": clean frame after the stream differs from the model";
}

void abort_and_check(rtl::RasterSim& sim, const std::string& what) {
  sim.write_reg(R(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_ABORT_Msk);
  sim.idle(2);
  const uint32_t st = sim.read_reg(R(STATUS));
  EXPECT_EQ(st & (RASTER_STATUS_BUSY_Msk | RASTER_STATUS_FIFO_EMPTY_Msk | RASTER_STATUS_FIFO_LEVEL_Msk),
            RASTER_STATUS_FIFO_EMPTY_Msk)
      << what << ": ABORT did not return the unit to idle (STATUS 0x" << std::hex << st << ")";
}

class RasterFuzz : public ::testing::TestWithParam<const char*> {};

// Random streams of mixed pieces: random words, random state words ahead of random records,
// well-formed extreme records, truncated triangles. Padded to whole 31-word groups, then the
// stream must finish within the bound and leave everything outside the frame untouched.
TEST_P(RasterFuzz, RandomStreamsBoundedAndInsideTheFrame) {
  const std::string name = GetParam();
  const ModelConfig cfg = rtl_config(name);
  rtl::RasterSim sim(name);
  std::mt19937 rng(name == std::string("full") ? 101 : 202);
  uint64_t groups = 0, fragments = 0, busy = 0;
  int err_state = 0;
  for (int iter = 0; iter < 150; ++iter) {
    const std::string what = name + " stream " + std::to_string(iter);
    FbLayout f;
    f.width = 4 + rng() % 45;
    f.height = 3 + rng() % 30;
    f.stride = f.width + rng() % 9;
    if (iter % 6 == 5) f.stride = f.width + 1 + rng() % 8;  // always a gap
    setup_frame(sim, f, static_cast<uint16_t>(rng()));
    Stream words(cfg, sim, f);
    // A plane record's random words, with a box inside the frame half the time (random edges and
    // planes then draw inside it), else random.
    auto random_word = [&]() {
      const uint32_t h = words.header_word();
      if ((h == 2 || h == 3) && (rng() & 1u)) {
        const uint32_t lim = h == 2 ? f.width : f.height;
        const uint32_t lo = rng() % lim, hi = lo + rng() % (lim - lo);
        return lo | (hi << 16);
      }
      return static_cast<uint32_t>(rng());
    };
    const int pieces = 4 + static_cast<int>(rng() % 10);
    for (int p = 0; p < pieces; ++p) {
      switch (rng() % 5) {
        case 0:  // random words
          for (uint32_t k = 1 + rng() % 40; k > 0; --k) words.word(random_word());
          break;
        case 1:  // a random state word ahead of a random record
          words.word(state_word(rng, false));
          for (size_t k = 0; k < fw::kTriangleWords; ++k) words.word(random_word());
          if (words.planes()) words.close(rng);
          break;
        case 2:  // truncated triangle
          words.word(state_word(rng, true));
          for (uint32_t k = rng() % fw::kTriangleWords; k > 0; --k) words.word(random_word());
          break;
        default:  // well-formed record at the extremes
          words.record(state_word(rng, true), extreme_record(rng, cfg, f));
          break;
      }
    }
    words.close(rng);
    if (!run_bounded(sim, words, f, name, what)) return;
    EXPECT_EQ(count_outside_writes(sim, f), 0u) << what << ": a write landed outside the " << f.width << "x"
                                                << f.height << " frame (stride " << f.stride << ")";
    // Counters are consistent: every triangle was taken.
    EXPECT_EQ(sim.read_reg(R(CNT_TRIANGLES)), words.groups()) << what;
    groups += words.groups();
    fragments += sim.read_reg(R(CNT_FRAGMENTS));
    busy += sim.read_reg(R(CNT_BUSY));
    err_state += (sim.read_reg(R(STATUS)) & RASTER_STATUS_ERR_STATE_Msk) != 0;
    sim.write_reg(R(STATUS), RASTER_STATUS_ERR_STATE_Msk);  // rw1c
    EXPECT_FALSE(sim.read_reg(R(STATUS)) & RASTER_STATUS_ERR_STATE_Msk) << what << ": ERR_STATE did not clear";
  }
  std::printf("%s: %llu groups, %llu fragments, %llu busy clocks, ERR_STATE in %d of the streams, %llu clocks in all\n",
              name.c_str(), static_cast<unsigned long long>(groups), static_cast<unsigned long long>(fragments),
              static_cast<unsigned long long>(busy), err_state, static_cast<unsigned long long>(sim.cycles()));
  EXPECT_GT(fragments, 0u);
  EXPECT_GT(err_state, 0);
  expect_clean_frame(sim, rng, cfg, name);
}

// A stream cut anywhere (a partial triangle waiting for words, the FIFO full with the unit
// disabled, or in the middle of drawing) then ABORT: always idle and empty at once, and a clean
// frame afterwards equals the model.
TEST_P(RasterFuzz, AbortAnywhereThenCleanFrame) {
  const std::string name = GetParam();
  const ModelConfig cfg = rtl_config(name);
  rtl::RasterSim sim(name);
  std::mt19937 rng(name == std::string("full") ? 303 : 404);
  const FbLayout f{48, 32, 56};
  for (int iter = 0; iter < 60; ++iter) {
    const std::string what = name + " abort " + std::to_string(iter);
    setup_frame(sim, f, static_cast<uint16_t>(rng()));
    Stream stream(cfg, sim, f);
    for (int t = 0; t < 3; ++t) stream.record(state_word(rng, true), extreme_record(rng, cfg, f));
    for (uint32_t k = rng() % 90; k > 0; --k) stream.word(rng());
    std::vector<uint32_t> words = stream.words();
    if (words.empty()) words.push_back(rng());
    words.resize(1 + rng() % words.size());
    switch (iter % 3) {
      case 0:  // disabled: words pile up (at most a FIFO's worth, or the bus write would hold)
        sim.write_reg(R(CTRL), 0);
        if (words.size() > 64) words.resize(64);
        sim.push_words(words);
        break;
      case 1:  // enabled, abort right after the last word
        sim.push_words(words);
        break;
      default:  // enabled, abort after a random delay (maybe mid-triangle, maybe idle)
        sim.push_words(words);
        sim.idle(rng() % 3000);
        break;
    }
    abort_and_check(sim, what);
    sim.write_reg(R(CTRL), RASTER_CTRL_ENABLE_Msk);
    EXPECT_EQ(count_outside_writes(sim, f), 0u) << what;
    if (iter % 4 == 3) expect_clean_frame(sim, rng, cfg, what);
  }
  expect_clean_frame(sim, rng, cfg, name + " abort end");
}

// Well-formed records at the extremes (vertices at the ends of the XW-bit range, far off-screen,
// zero-area) with random untextured states: the frame equals the model's for the same records.
TEST_P(RasterFuzz, ExtremeRecordsEqualTheModel) {
  const std::string name = GetParam();
  const ModelConfig cfg = rtl_config(name);
  rtl::RasterSim sim(name);
  std::mt19937 rng(name == std::string("full") ? 505 : 606);
  for (int iter = 0; iter < 40; ++iter) {
    const std::string what = name + " extreme " + std::to_string(iter);
    const FbLayout f{static_cast<uint32_t>(8 + rng() % 40), static_cast<uint32_t>(6 + rng() % 30), 0};
    const FbLayout fs{f.width, f.height, f.width};
    RecordScene scene;
    scene.width = static_cast<int>(f.width);
    scene.height = static_cast<int>(f.height);
    scene.clear_color = static_cast<uint16_t>(rng());
    Stream words(cfg, sim, fs);
    for (int t = 0; t < 8; ++t) {
      RecordTriangle rt;
      rt.record = extreme_record(rng, cfg, fs);
      rt.state.textured = false;
      rt.state.depth_func = static_cast<DepthFunc>(rng() % 6);
      rt.state.depth_write = rng() & 1u;
      rt.state.gouraud = rng() & 1u;
      rt.state.method = Method::RecipNr;
      words.record(pack_state_word(rt.state, rt.state.method), rt.record);
      scene.tris.push_back(rt);
    }
    setup_frame(sim, fs, scene.clear_color);
    if (!run_bounded(sim, words, fs, name, what)) return;
    const htx::Frame m = render_model_records(scene, cfg);
    const uint32_t n = f.width * f.height;
    const std::vector<uint16_t> c = sim.read_color(n);
    const std::vector<uint32_t> z = sim.read_depth(n);
    uint32_t bad = 0;
    for (uint32_t i = 0; i < n; ++i) bad += (c[i] != m.color[i]) || ((z[i] & 0xFFFFFFu) != m.depth[i]);
    EXPECT_EQ(bad, 0u) << what << ": " << f.width << "x" << f.height;
    EXPECT_EQ(sim.read_reg(R(CNT_FRAGMENTS)), m.counters.fragments) << what;
    EXPECT_FALSE(sim.read_reg(R(STATUS)) & RASTER_STATUS_ERR_STATE_Msk) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Configs, RasterFuzz, ::testing::Values("full", "icebreaker"));

}  // namespace
}  // namespace htx
