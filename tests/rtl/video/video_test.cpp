// htx_video (docs/video.md) on its own: the 640x480 at 60 Hz timing on its output pins, the
// framebuffer shown scaled x4 while its port refuses reads at random (as the raster's colour writes
// make htx_fb's port do), the registers, the frame taken at its start, and an underrun when the
// port refuses every read, and the page flip taken at a frame's start (label `rtl`). The model
// is built with three colour pages (CMakeLists.txt: Pages = 3, page p from word p x 9,600).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "Vhtx_video.h"
#include "Vhtx_video_1p.h"
#include "htx/model/image_io.hpp"
#include "htx/sim/video_capture.hpp"
#include "htx_regs.h"
#include "vmodel_clock.hpp"

namespace {

constexpr uint32_t kSrcW = 160, kSrcH = 120, kScale = 4;
constexpr uint32_t kW = 640, kH = 480, kHTotal = 800, kVTotal = 525;
constexpr uint32_t kPageWords = kSrcW * kSrcH / 2;

template <class Model>
struct BenchOf {
  Model v;
  std::vector<uint32_t> fb = std::vector<uint32_t>(3 * kPageWords);  // pages 0, 1 and 2
  std::mt19937 rng{20261205};
  unsigned refuse_percent = 0;  // a read is refused in this share of the clocks it is asked in
  uint32_t word_read = 0;       // the word of the last granted read, on fb_data_i until the next
  uint64_t reads = 0;

  BenchOf() {
    v.req_valid_i = 0;
    v.fb_gnt_i = 0;
    htx::raster_test::reset_model(v);
  }

  // One clock, with a register request (offset in VIDEO's block) presented in it if `req`.
  void clock(bool req = false, uint32_t offset = 0, bool we = false, uint32_t wdata = 0, unsigned be = 0xF) {
    v.req_valid_i = req;
    v.req_addr_i = HTX_VIDEO_BASE + offset;
    v.req_we_i = we;
    v.req_be_i = be;
    v.req_wdata_i = wdata;
    v.fb_data_i = word_read;
    v.fb_gnt_i = 0;
    v.eval();
    const bool gnt = v.fb_req_o && (rng() % 100) >= refuse_percent;
    const uint32_t addr = v.fb_addr_o;
    v.fb_gnt_i = gnt;
    htx::raster_test::clock_edge(v);
    if (gnt) {
      word_read = fb.at(addr);
      ++reads;
    }
  }
  void write(uint32_t offset, uint32_t value) {
    clock(true, offset, true, value);
    clock();
    clock();
  }
  uint32_t read(uint32_t offset) {
    clock(true, offset);
    clock();
    EXPECT_TRUE(v.rsp_valid_o);
    const uint32_t r = v.rsp_rdata_o;
    clock();
    return r;
  }
  // Clocks until the vertical sync pulse begins (at most two frames).
  void to_vsync() {
    bool was_high = v.vsync_no;
    for (uint32_t i = 0; i < 2 * kHTotal * kVTotal; ++i) {
      clock();
      if (was_high && !v.vsync_no) return;
      was_high = v.vsync_no;
    }
    FAIL() << "no vertical sync in two frames";
  }
  // The next whole frame's 640 x 480 visible pixels (RGB888), as a monitor sees them.
  std::vector<uint32_t> capture() {
    htx::sim::VideoCapture monitor;
    for (uint32_t i = 0; i < 2 * kHTotal * kVTotal && monitor.frames() == 0; ++i) {
      clock();
      monitor.clock(v.de_o, v.vsync_no, v.rgb_o);
    }
    return monitor.last_frame();
  }
};
using Bench = BenchOf<Vhtx_video>;

uint16_t pixel(const std::vector<uint32_t>& fb, uint32_t x, uint32_t y) {
  const uint32_t i = y * kSrcW + x;
  return static_cast<uint16_t>(fb[i / 2] >> (16 * (i % 2)));
}

TEST(Video, TimingIsVesa640x480At60Hz) {
  Bench b;
  b.to_vsync();
  // Two frames from the start of a vertical sync, one clock at a time.
  std::vector<uint8_t> de, hs, vs;
  for (uint32_t i = 0; i < 2 * kHTotal * kVTotal; ++i) {
    de.push_back(b.v.de_o);
    hs.push_back(b.v.hsync_no);
    vs.push_back(b.v.vsync_no);
    EXPECT_EQ(b.v.rgb_o, 0u) << "disabled, the picture is black";
    b.clock();
  }
  EXPECT_EQ(b.reads, 0u) << "disabled, the unit reads no memory";
  // Vertical sync: low for 2 lines, once a frame of 525 lines.
  for (uint32_t f = 0; f < 2; ++f) {
    for (uint32_t i = 0; i < kHTotal * kVTotal; ++i) {
      ASSERT_EQ(vs[f * kHTotal * kVTotal + i], i < 2 * kHTotal ? 0 : 1) << "clock " << i << " of frame " << f;
    }
  }
  // From the sync's start: 33 + 2 - 2 lines of blanking (back porch), then 480 lines of 640 visible
  // pixels starting with the line, each line's horizontal sync 656 clocks after its start for 96.
  const uint32_t first_visible = (2 + 33) * kHTotal;
  for (uint32_t i = 0; i < kHTotal * kVTotal; ++i) {
    const uint32_t line = i / kHTotal, h = i % kHTotal;
    const uint32_t vline = (line + kVTotal - (first_visible / kHTotal)) % kVTotal;  // 0 = first visible
    const bool visible = vline < kH && h < kW;
    ASSERT_EQ(de[i], visible ? 1 : 0) << "line " << vline << " clock " << h;
    ASSERT_EQ(hs[i], (h >= 656 && h < 752) ? 0 : 1) << "line " << vline << " clock " << h;
  }
}

TEST(Video, ShowsTheFramebufferScaledWhileItsPortRefusesHalfTheReads) {
  Bench b;
  for (auto& w : b.fb) w = b.rng();
  b.refuse_percent = 50;
  b.write(VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk);
  const std::vector<uint32_t> px = b.capture();
  ASSERT_EQ(px.size(), kW * kH);
  for (uint32_t y = 0; y < kH; ++y) {
    for (uint32_t x = 0; x < kW; ++x) {
      ASSERT_EQ(px[y * kW + x], htx::rgb888_from_rgb565(pixel(b.fb, x / kScale, y / kScale)))
          << "x " << x << " y " << y;
    }
  }
  const uint32_t status = b.read(VIDEO_STATUS_Offset);
  EXPECT_EQ(status & VIDEO_STATUS_UNDERRUN_Msk, 0u);
  EXPECT_NE(status & VIDEO_STATUS_SHOWING_Msk, 0u);
  // Each framebuffer line is read once a frame: 9,600 words (and at most the next frame's first).
  EXPECT_GE(b.reads, kSrcW * kSrcH / 2);
  EXPECT_LE(b.reads, kSrcW * kSrcH / 2 + 2 * kSrcW);
}

TEST(Video, RegistersCountFramesAndLinesAndDescribeTheMode) {
  Bench b;
  EXPECT_EQ(b.read(VIDEO_MODE_Offset), kSrcW | (kSrcH << 12) | (kScale << 24) | (3u << VIDEO_MODE_PAGES_Pos));
  EXPECT_EQ(b.read(VIDEO_CTRL_Offset), 0u);
  b.write(VIDEO_CTRL_Offset, 1);
  EXPECT_EQ(b.read(VIDEO_CTRL_Offset), 1u);
  b.to_vsync();
  const uint32_t line = b.read(VIDEO_LINE_Offset);
  EXPECT_EQ(line, 490u) << "the sync pulse is lines 490 and 491";
  EXPECT_NE(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_VBLANK_Msk, 0u);
  const uint32_t frames = b.read(VIDEO_FRAME_Offset);
  b.to_vsync();
  b.to_vsync();
  EXPECT_EQ(b.read(VIDEO_FRAME_Offset), frames + 2);
  // Mid-frame (line 100 or so), not in blanking.
  for (uint32_t i = 0; i < 135 * kHTotal; ++i) b.clock();
  EXPECT_EQ(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_VBLANK_Msk, 0u);
  // A partial write is ignored.
  b.clock(true, VIDEO_CTRL_Offset, true, 0, 0x1);
  b.clock();
  b.clock();
  EXPECT_EQ(b.read(VIDEO_CTRL_Offset), 1u);
}

TEST(Video, EnableTakesEffectAtTheFrameStartAndStopsTheReads) {
  Bench b;
  for (auto& w : b.fb) w = 0xFFFFFFFFu;
  b.write(VIDEO_CTRL_Offset, 1);
  std::vector<uint32_t> px = b.capture();
  ASSERT_EQ(px.size(), kW * kH);
  EXPECT_EQ(px[0], 0xFFFFFFu);
  // Cleared in the middle of a shown frame (line 40): that frame stays whole, the next is black,
  // unread.
  b.to_vsync();
  for (uint32_t i = 0; i < (35 + 40) * kHTotal; ++i) b.clock();
  b.write(VIDEO_CTRL_Offset, 0);
  EXPECT_NE(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_SHOWING_Msk, 0u);
  uint32_t white_after_clear = 0;
  for (uint32_t i = 0; i < kHTotal * 400; ++i) {
    b.clock();
    if (b.v.de_o && b.v.rgb_o == 0xFFFFFFu) ++white_after_clear;
  }
  EXPECT_EQ(white_after_clear, kW * 400) << "the rest of the frame is shown";
  b.to_vsync();
  const uint64_t reads_before = b.reads;
  px = b.capture();
  ASSERT_EQ(px.size(), kW * kH);
  for (uint32_t p : px) ASSERT_EQ(p, 0u);
  EXPECT_EQ(b.reads, reads_before);
  EXPECT_EQ(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_SHOWING_Msk, 0u);
}

// Page 0 white, page 1 blue. CTRL.PAGE written in the middle of a frame: that frame stays on page
// 0 to its end and STATUS.PAGE with it; the next frame is page 1's, read from page 1's words only.
TEST(Video, APageFlipTakesEffectAtTheFrameStart) {
  Bench b;
  for (uint32_t i = 0; i < kPageWords; ++i) {
    b.fb[i] = 0xFFFFFFFFu;
    b.fb[kPageWords + i] = 0x001F001Fu;
    b.fb[2 * kPageWords + i] = 0xF800F800u;
  }
  const uint32_t page1 = 1u << VIDEO_CTRL_PAGE_Pos, page2 = 2u << VIDEO_CTRL_PAGE_Pos;
  b.write(VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk);
  std::vector<uint32_t> px = b.capture();
  ASSERT_EQ(px.size(), kW * kH);
  EXPECT_EQ(std::count(px.begin(), px.end(), 0xFFFFFFu), kW * kH);
  EXPECT_EQ(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_PAGE_Msk, 0u);
  b.to_vsync();
  for (uint32_t i = 0; i < (35 + 200) * kHTotal; ++i) b.clock();  // line 200 or so
  b.write(VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk | page1);
  EXPECT_EQ(b.read(VIDEO_CTRL_Offset), VIDEO_CTRL_ENABLE_Msk | page1);
  EXPECT_EQ(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_PAGE_Msk, 0u) << "not before the frame's end";
  uint32_t white = 0, other = 0;
  for (uint32_t i = 0; i < kHTotal * kVTotal && b.v.vsync_no; ++i) {  // to the frame's sync pulse
    b.clock();
    if (b.v.de_o) ++(b.v.rgb_o == 0xFFFFFFu ? white : other);
  }
  EXPECT_GT(white, kW * 200);
  EXPECT_EQ(other, 0u) << "the frame the flip was written in stays whole";
  const uint64_t reads_before = b.reads;
  px = b.capture();
  ASSERT_EQ(px.size(), kW * kH);
  EXPECT_EQ(std::count(px.begin(), px.end(), 0x0000FFu), kW * kH);
  EXPECT_EQ((b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_PAGE_Msk) >> VIDEO_STATUS_PAGE_Pos, 1u);
  EXPECT_GE(b.reads - reads_before, kPageWords);
  // Page 2 at the next start; a page the memory does not have (3) leaves CTRL.PAGE as it was.
  b.write(VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk | page2);
  b.write(VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk | (3u << VIDEO_CTRL_PAGE_Pos));
  EXPECT_EQ(b.read(VIDEO_CTRL_Offset), VIDEO_CTRL_ENABLE_Msk | page2);
  b.to_vsync();
  px = b.capture();
  EXPECT_EQ(std::count(px.begin(), px.end(), 0xFF0000u), kW * kH);
  EXPECT_EQ((b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_PAGE_Msk) >> VIDEO_STATUS_PAGE_Pos, 2u);
  // Back to page 0 at the next start.
  b.write(VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk);
  b.to_vsync();
  px = b.capture();
  EXPECT_EQ(std::count(px.begin(), px.end(), 0xFFFFFFu), kW * kH);
}

// Built with one page (the UP5K's SPRAM framebuffer): MODE says so, CTRL.PAGE reads 0 whatever is
// written, and the frame is read from page 0.
TEST(Video, WithOnePageThePageIsAlwaysZero) {
  BenchOf<Vhtx_video_1p> b;
  for (uint32_t i = 0; i < kPageWords; ++i) b.fb[i] = 0xFFFFFFFFu;
  EXPECT_EQ(b.read(VIDEO_MODE_Offset) >> VIDEO_MODE_PAGES_Pos, 1u);
  for (uint32_t page = 1; page < 4; ++page) {
    b.write(VIDEO_CTRL_Offset, VIDEO_CTRL_ENABLE_Msk | (page << VIDEO_CTRL_PAGE_Pos));
    EXPECT_EQ(b.read(VIDEO_CTRL_Offset), VIDEO_CTRL_ENABLE_Msk) << page;
  }
  const std::vector<uint32_t> px = b.capture();
  ASSERT_EQ(px.size(), kW * kH);
  EXPECT_EQ(std::count(px.begin(), px.end(), 0xFFFFFFu), kW * kH);
  EXPECT_EQ(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_PAGE_Msk, 0u);
}

TEST(Video, APortThatRefusesEveryReadSetsUnderrunWhichAWriteOfOneClears) {
  Bench b;
  b.write(VIDEO_CTRL_Offset, 1);
  b.refuse_percent = 100;
  b.capture();
  EXPECT_EQ(b.reads, 0u);
  EXPECT_NE(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_UNDERRUN_Msk, 0u);
  // The port serves again: the flag stays until cleared, then stays clear.
  b.refuse_percent = 0;
  b.capture();
  EXPECT_NE(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_UNDERRUN_Msk, 0u);
  b.write(VIDEO_STATUS_Offset, 0);
  EXPECT_NE(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_UNDERRUN_Msk, 0u) << "writing 0 leaves it";
  b.write(VIDEO_STATUS_Offset, VIDEO_STATUS_UNDERRUN_Msk);
  EXPECT_EQ(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_UNDERRUN_Msk, 0u);
  b.capture();
  EXPECT_EQ(b.read(VIDEO_STATUS_Offset) & VIDEO_STATUS_UNDERRUN_Msk, 0u);
}

}  // namespace

namespace {

// The harness's monitor (hw/platform/sim/video_capture.hpp) on made-up pins: a frame cut short by
// the next sync pulse is dropped and counted, a whole one kept.
TEST(VideoCapture, KeepsWholeFramesAndDropsCutOnes) {
  htx::sim::VideoCapture m(4, 2);
  auto sync = [&] {
    m.clock(false, true, 0);
    m.clock(false, false, 0);
    m.clock(false, true, 0);
  };
  for (uint32_t i = 0; i < 8; ++i) m.clock(true, true, 100 + i);  // before any sync: not a frame
  EXPECT_EQ(m.frames(), 0u);
  sync();
  for (uint32_t i = 0; i < 5; ++i) m.clock(true, true, i);  // 5 of 8, then a sync: cut
  sync();
  EXPECT_EQ(m.frames(), 0u);
  EXPECT_EQ(m.cut_frames(), 1u);
  for (uint32_t i = 0; i < 10; ++i) m.clock(i % 5 != 4, true, 10 + i);  // 8 with de among 10
  EXPECT_EQ(m.frames(), 1u);
  EXPECT_EQ(m.last_frame(), (std::vector<uint32_t>{10, 11, 12, 13, 15, 16, 17, 18}));
  m.clock(true, true, 99);  // after a whole frame, nothing until the next sync
  sync();
  EXPECT_EQ(m.cut_frames(), 1u);
  EXPECT_EQ(m.last_frame().size(), 8u);
}

}  // namespace
