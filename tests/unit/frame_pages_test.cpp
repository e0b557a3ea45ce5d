// The console's colour pages (firmware/app/console/frame_pages.cpp, docs/video.md "Double
// buffering") over the HAL's FakeBus, with the video's STATUS.PAGE scripted: a render draws into a
// page neither shown nor asked for, with three pages without waiting to begin; a new frame is asked
// for only once the one before it is shown; with two pages a render waits for the last flip; every
// wait ends within its poll bound; with one page nothing is written.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "frame_pages.hpp"
#include "htx/hal/framebuffer.h"
#include "htx/hal/sim/fake_bus.hpp"
#include "htx/hal/video.h"

namespace {

using htx::hal::sim::FakeBus;
using htx::hal::sim::ScopedBus;

constexpr uint32_t kFbPage = HTX_RASTER_BASE + RASTER_FB_PAGE_Offset;
constexpr uint32_t kCtrl = HTX_VIDEO_BASE + VIDEO_CTRL_Offset;
constexpr uint32_t kStatus = HTX_VIDEO_BASE + VIDEO_STATUS_Offset;

// A bus with `pages` colour pages and a video whose STATUS.PAGE becomes CTRL.PAGE after `delay`
// reads of STATUS once CTRL.PAGE has changed (never when delay < 0).
struct Video {
  FakeBus bus;
  int delay = 0;
  int reads_since_request = 0;
  uint32_t shown = 0;

  explicit Video(uint32_t pages) {
    bus.poke(HTX_RASTER_BASE + RASTER_FB_MEM_Offset, 19200u | (pages << RASTER_FB_MEM_PAGES_Pos));
    bus.poke(HTX_VIDEO_BASE + VIDEO_MODE_Offset, pages << VIDEO_MODE_PAGES_Pos);
    bus.poke(kCtrl, VIDEO_CTRL_ENABLE_Msk);
    bus.on_write(kCtrl, [this](uint32_t) { reads_since_request = 0; });
    bus.on_read(kStatus, [this] {
      const uint32_t requested = (bus.peek(kCtrl) & VIDEO_CTRL_PAGE_Msk) >> VIDEO_CTRL_PAGE_Pos;
      if (delay >= 0 && reads_since_request++ >= delay) shown = requested;
      return shown << VIDEO_STATUS_PAGE_Pos;
    });
  }
  uint32_t draw_page() const { return (bus.peek(kFbPage) & RASTER_FB_PAGE_DRAW_Msk) >> RASTER_FB_PAGE_DRAW_Pos; }
  uint32_t requested() const { return (bus.peek(kCtrl) & VIDEO_CTRL_PAGE_Msk) >> VIDEO_CTRL_PAGE_Pos; }
};

constexpr uint32_t kPolls = 1000;

TEST(FramePages, ThreePagesDrawWhileTheLastFrameWaitsAndShowEveryFrame) {
  Video v(3);
  ScopedBus attach(v.bus);
  EXPECT_EQ(console_app::frame_pages(), 3u);
  v.delay = 5;  // a flip takes five status reads after it is asked for
  std::vector<uint32_t> drawn;
  for (int frame = 0; frame < 6; ++frame) {
    v.bus.clear_log();
    console_app::begin_frame_page(kPolls);
    const uint32_t draw = v.draw_page();
    EXPECT_NE(draw, v.requested()) << "frame " << frame << ": the frame waiting to be shown";
    EXPECT_NE(draw, v.shown) << "frame " << frame << ": the page on the screen";
    EXPECT_LE(v.bus.reads_of(kStatus), 1u) << "frame " << frame << ": began without waiting";
    drawn.push_back(draw);
    const uint32_t before = v.requested();
    console_app::present_frame_page(kPolls);
    EXPECT_EQ(v.requested(), draw);
    // The request came only once the frame before it was on the screen.
    const auto& log = v.bus.log();
    uint32_t last_shown = ~0u;
    for (const auto& a : log) {
      if (!a.write && a.addr == kStatus) last_shown = (a.value & VIDEO_STATUS_PAGE_Msk) >> VIDEO_STATUS_PAGE_Pos;
      if (a.write && a.addr == kCtrl) {
        EXPECT_EQ(last_shown, before) << "frame " << frame;
        EXPECT_NE(a.value & VIDEO_CTRL_ENABLE_Msk, 0u) << "the enable stays";
      }
    }
  }
  // All three pages take turns.
  EXPECT_EQ(drawn, (std::vector<uint32_t>{1, 2, 0, 1, 2, 0}));
}

TEST(FramePages, TwoPagesWaitForTheLastFlipBeforeDrawing) {
  Video v(2);
  ScopedBus attach(v.bus);
  v.delay = 7;
  console_app::begin_frame_page(kPolls);
  EXPECT_EQ(v.draw_page(), 1u);
  console_app::present_frame_page(kPolls);
  EXPECT_EQ(v.requested(), 1u);
  v.bus.clear_log();
  console_app::begin_frame_page(kPolls);
  EXPECT_EQ(v.shown, 1u) << "the flip was taken first";
  EXPECT_GE(v.bus.reads_of(kStatus), 7u);
  EXPECT_EQ(v.draw_page(), 0u);
}

TEST(FramePages, AVideoThatNeverFlipsCostsAtMostThePollBound) {
  for (uint32_t pages : {2u, 3u}) {
    Video v(pages);
    ScopedBus attach(v.bus);
    v.delay = -1;
    v.bus.poke(kCtrl, VIDEO_CTRL_ENABLE_Msk | (1u << VIDEO_CTRL_PAGE_Pos));  // asked for 1, showing 0
    v.bus.clear_log();
    console_app::begin_frame_page(kPolls);
    // Two pages: the page not asked for (drawn while shown); three: the free one.
    EXPECT_EQ(v.draw_page(), pages == 2 ? 0u : 2u) << pages;
    console_app::present_frame_page(kPolls);
    EXPECT_LE(v.bus.reads_of(kStatus), 2 * kPolls + 2) << pages;
    EXPECT_EQ(v.requested(), v.draw_page()) << pages;
  }
}

TEST(FramePages, OnePageWritesNothing) {
  Video v(1);
  ScopedBus attach(v.bus);
  v.bus.clear_log();
  EXPECT_EQ(console_app::frame_pages(), 1u);
  console_app::begin_frame_page(kPolls);
  console_app::present_frame_page(kPolls);
  EXPECT_TRUE(v.bus.writes_to(kFbPage).empty());
  EXPECT_TRUE(v.bus.writes_to(kCtrl).empty());
}

}  // namespace
