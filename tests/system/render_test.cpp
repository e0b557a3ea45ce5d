// The render firmware (firmware/app/render) on the simulated SoC: its compiled-in scenes are the
// model's built-in scenes, its configuration constants are the icebreaker raster unit's, and the
// frame it draws on `htx sim` has the checksum of the cosim frame: the same firmware render code
// and texture upload compiled for the host over hal/sim, on the Verilated icebreaker GPU (raster and
// texture units), with the same scenes, texture and render state (whose frame equals the model's
// for the same vertex records and texture).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "htx/hal/framebuffer.h"
#include "htx/hal/raster.h"
#include "htx/hal/sim/gpu_sim_bus.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/model.hpp"
#include "htx/model/proc_textures.hpp"
#include "htx/model/scenes.hpp"
#include "htx/model/texture.hpp"
#include "htx/render/frame.h"
#include "htx/render/scene_pack.h"
#include "htx/render/texture_pack.h"
#include "htx/render/texture_upload.h"
#include "htx/hal/texture.h"
#include "htx/fw/console_packet.h"
#include "htx/fw/crc32.h"
#include "htx/fw/texel.h"
#include "console_payload.hpp"
#include "frame_records.hpp"
#include "hal_frame.hpp"
#include "htx/rtl/raster_engine.hpp"
#include "render_scene.hpp"
#include "render_state.hpp"
#include "scene_render.hpp"
#include "scene_turn.hpp"
#include "scenes.hpp"
#include "soc_config.hpp"
#include "soc_texture.hpp"
#include "sim_json.hpp"
#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

// Bitwise CRC-32 (IEEE, zlib's), written apart from the firmware's and the harness's table versions.
uint32_t crc32_bitwise(const std::vector<uint16_t>& pixels) {
  uint32_t crc = 0xFFFFFFFFu;
  for (uint16_t p : pixels)
    for (uint32_t byte : {uint32_t{p} & 0xFFu, uint32_t{p} >> 8}) {
      crc ^= byte;
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ ((crc & 1u) ? 0xEDB88320u : 0u);
    }
  return ~crc;
}

std::string hex8(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08x", v);
  return buf;
}

uint32_t field(uint32_t word, uint32_t pos, uint32_t mask) { return (word & mask) >> pos; }

htx::TriState unpack_state_word(uint32_t w) {
  htx::TriState s;
  s.method = static_cast<htx::Method>(field(w, RASTER_STATE_METHOD_Pos, RASTER_STATE_METHOD_Msk));
  s.subdiv_n = field(w, RASTER_STATE_SUBDIV_N_Pos, RASTER_STATE_SUBDIV_N_Msk);
  s.filter = static_cast<htx::Filter>(field(w, RASTER_STATE_FILTER_Pos, RASTER_STATE_FILTER_Msk));
  s.wrap_u = static_cast<htx::Wrap>(field(w, RASTER_STATE_WRAP_U_Pos, RASTER_STATE_WRAP_U_Msk));
  s.wrap_v = static_cast<htx::Wrap>(field(w, RASTER_STATE_WRAP_V_Pos, RASTER_STATE_WRAP_V_Msk));
  s.depth_func = static_cast<htx::DepthFunc>(field(w, RASTER_STATE_DEPTH_FUNC_Pos, RASTER_STATE_DEPTH_FUNC_Msk));
  s.depth_write = field(w, RASTER_STATE_DEPTH_WRITE_Pos, RASTER_STATE_DEPTH_WRITE_Msk) != 0;
  s.textured = field(w, RASTER_STATE_TEXTURED_Pos, RASTER_STATE_TEXTURED_Msk) != 0;
  s.gouraud = field(w, RASTER_STATE_GOURAUD_Pos, RASTER_STATE_GOURAUD_Msk) != 0;
  s.combine = static_cast<htx::Combine>(field(w, RASTER_STATE_COMBINE_Pos, RASTER_STATE_COMBINE_Msk));
  s.texture = static_cast<int>(field(w, RASTER_STATE_TEXTURE_Pos, RASTER_STATE_TEXTURE_Msk));
  return s;
}

// The cosim frame of a built-in scene: the model's scene converted as the cosim tests do, the
// firmware's texture and render state, firmware/render over hal/sim on the Verilated icebreaker GPU.
struct CosimFrame {
  std::vector<uint16_t> color;
  uint32_t raster_busy = 0;
  uint32_t sent = 0;
};

// `filter`: every mesh's filter (the console's `set filter`), or kSceneFilter for the scene's own;
// `method`: every mesh's method (the console's `set method`; AUTO within 1/16 texel by default).
CosimFrame cosim_frame(const std::string& scene_name, uint8_t filter = render_app::kSceneFilter,
                       uint8_t method = htx::render::kMethodAuto) {
  using namespace htx;
  constexpr int kW = render_app::kWidth, kH = render_app::kHeight;
  test::RenderScene rs = test::to_render_scene(make_builtin_scene(scene_name), kW, kH);
  std::vector<render::Mesh> meshes;
  uint32_t max_vertices = 0;
  for (auto& d : rs.meshes) {
    render_app::apply_soc_render_state(&d.mesh);
    if (filter != render_app::kSceneFilter) d.mesh.state.filter = filter;
    d.mesh.state.method = method;
    meshes.push_back(d.mesh);
    max_vertices = std::max(max_vertices, d.mesh.vertex_count);
  }
  const ModelConfig cfg = rtl_config("icebreaker");
  hal::sim::GpuSimBus bus("icebreaker");
  hal::sim::ScopedBus attach(bus);
  std::vector<uint32_t> image(render_app::kTextureTexels);
  if (render_app::upload_scene_texture(1000, image.data()) != render::kUploadOk)
    throw std::runtime_error("cosim texture upload failed");
  render::FrameParams frame;
  frame.viewport = {kW, kH};
  frame.format = cfg.record_format();
  frame.methods_built = cfg.methods;
  frame.auto_config = fw::auto_config_of(cfg);
  frame.auto_tolerance = render::kOne / 16;  // issue 7's tolerance
  frame.cull_backfaces = rs.cull_backfaces;
  std::vector<render::ClipVert> clip(max_vertices);
  std::vector<render::ScreenVert> screen(max_vertices);
  std::vector<uint8_t> codes(max_vertices);
  render::VertexCache cache{clip.data(), screen.data(), codes.data(), max_vertices};
  render::DrawStats stats;
  render::DrawStatus mesh_status = render::kDrawOk;
  const render::FrameStatus st =
      render::render_frame(frame, {render_app::kClearColor, render_app::kClearDepth}, rs.view_proj, meshes.data(),
                           static_cast<uint32_t>(meshes.size()), &cache, 20'000'000, &stats, &mesh_status);
  if (st != render::kFrameOk) throw std::runtime_error("cosim render_frame failed: " + std::to_string(st));
  CosimFrame out;
  out.color = test::read_frame_through_hal(kW, kH, 0).color;
  hal::RasterCounters counters;
  hal::raster_read_counters(&counters);
  out.raster_busy = counters.busy;
  out.sent = stats.sent;

  // The cosim frame is the model's frame for the records the firmware code streamed.
  RecordScene records;
  records.width = kW;
  records.height = kH;
  records.clear_color = render_app::kClearColor;
  records.clear_depth = render_app::kClearDepth;
  std::vector<uint32_t> texels(render_app::kTextureTexels);
  render_app::checker_texels(texels.data());
  std::vector<uint8_t> bytes;
  for (uint32_t t : texels)
    for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<uint8_t>(t >> (8 * b)));
  records.textures.push_back(
      make_texture(TexFormat::RGB565, render_app::kTextureLog2, render_app::kTextureLog2, bytes));
  const test::FrameRecords fr =
      test::frame_records(bus.fifo_words(), HTX_RASTER->CAPS, cfg, frame, rs.view_proj, meshes.data(),
                          static_cast<uint32_t>(meshes.size()), &cache);
  for (const test::CapturedTriangle& t : fr.tris)
    records.tris.push_back({t.record, unpack_state_word(t.state_word)});
  const Frame model = render_model_records(records, cfg);
  if (model.color != out.color) throw std::runtime_error("cosim frame differs from the model's frame");
  return out;
}

struct SceneReport {
  std::map<std::string, std::string> fields;  // "vertices" -> "24", ...
};

// Parses the firmware's "render <scene> key value key value ..." lines.
std::map<std::string, SceneReport> parse_report(const std::string& out) {
  std::map<std::string, SceneReport> r;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag, scene, key, value;
    if (!(words >> tag >> scene) || tag != "render") continue;
    SceneReport& s = r[scene];
    while (words >> key >> value) s.fields[key] = value;
  }
  return r;
}

TEST(SystemRender, CompiledInScenesEqualTheModelsScenes) {
  uint32_t n = 0;
  const render_app::SceneData* scenes = render_app::builtin_scenes(&n);
  ASSERT_EQ(n, 2u);
  for (uint32_t s = 0; s < n; ++s) {
    const render_app::SceneData& fw = scenes[s];
    SCOPED_TRACE(fw.name);
    const htx::test::RenderScene rs =
        htx::test::to_render_scene(htx::make_builtin_scene(fw.name), render_app::kWidth, render_app::kHeight);
    EXPECT_EQ(fw.cull_backfaces, rs.cull_backfaces);
    EXPECT_EQ(0, std::memcmp(&fw.view_proj, &rs.view_proj, sizeof fw.view_proj));
    ASSERT_EQ(fw.mesh_count, rs.meshes.size());
    for (uint32_t m = 0; m < fw.mesh_count; ++m) {
      const htx::render::Mesh& a = fw.meshes[m];
      const htx::render::Mesh& b = rs.meshes[m].mesh;
      ASSERT_EQ(a.vertex_count, b.vertex_count);
      ASSERT_EQ(a.triangle_count, b.triangle_count);
      for (uint32_t i = 0; i < a.vertex_count; ++i) {
        const auto &va = a.vertices[i], &vb = b.vertices[i];
        EXPECT_TRUE(va.x == vb.x && va.y == vb.y && va.z == vb.z && va.s == vb.s && va.t == vb.t && va.rgba == vb.rgba)
            << "vertex " << i;
      }
      for (uint32_t i = 0; i < 3 * a.triangle_count; ++i) EXPECT_EQ(a.indices[i], b.indices[i]) << "index " << i;
      EXPECT_EQ(0, std::memcmp(&a.model, &b.model, sizeof a.model));
      EXPECT_EQ(a.position_bits, b.position_bits);
      EXPECT_EQ(a.tex.log2_width, b.tex.log2_width);
      EXPECT_EQ(a.tex.log2_height, b.tex.log2_height);
      // The firmware overrides textured, texture, its size, gouraud and method (render_state.hpp); the
      // rest is the scene's.
      EXPECT_EQ(a.state.subdiv_n, b.state.subdiv_n);
      EXPECT_EQ(a.state.filter, b.state.filter);
      EXPECT_EQ(a.state.depth_func, b.state.depth_func);
      EXPECT_EQ(a.state.depth_write, b.state.depth_write);
      EXPECT_EQ(a.state.combine, b.state.combine);
    }
  }
}

// The console's `spin` (firmware/app/console/scene_turn.cpp) turns each compiled-in scene about
// the vertical line through the middle of its bounding box (found here apart, in double): a half
// turn draws each vertex where the original draws its mirror image through that line (so `floor`,
// far from the world's origin, stays in view), and the turns keep the line itself in place.
TEST(SystemRender, SpinTurnsEachSceneAboutItsMiddle) {
  uint32_t n = 0;
  const render_app::SceneData* scenes = render_app::builtin_scenes(&n);
  for (uint32_t s = 0; s < n; ++s) {
    const render_app::SceneData& sc = scenes[s];
    SCOPED_TRACE(sc.name);
    double lo[2] = {1e30, 1e30}, hi[2] = {-1e30, -1e30};
    std::vector<htx::render::Vec4> world;
    for (uint32_t m = 0; m < sc.mesh_count; ++m)
      for (uint32_t i = 0; i < sc.meshes[m].vertex_count; ++i) {
        const auto& v = sc.meshes[m].vertices[i];
        world.push_back(htx::render::transform_point(sc.meshes[m].model, v.x, v.y, v.z));
        const double xz[2] = {world.back().x / 65536.0, world.back().z / 65536.0};
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], xz[k]), hi[k] = std::max(hi[k], xz[k]);
      }
    ASSERT_FALSE(world.empty());
    const double cx = (lo[0] + hi[0]) / 2, cz = (lo[1] + hi[1]) / 2;
    const console_app::TurnAxis axis = console_app::scene_turn_axis(sc);
    EXPECT_NEAR(axis.x / 65536.0, cx, 1e-4);
    EXPECT_NEAR(axis.z / 65536.0, cz, 1e-4);
    const auto clip = [](const htx::render::Mat4& m, int32_t x, int32_t y, int32_t z) {
      const htx::render::Vec4 c = htx::render::transform_point(m, x, y, z);
      return std::array<double, 4>{c.x / 65536.0, c.y / 65536.0, c.z / 65536.0, c.w / 65536.0};
    };
    const auto q16 = [](double v) { return static_cast<int32_t>(std::lround(v * 65536.0)); };
    const render_app::SceneData half = console_app::turned_scene(sc, axis, 0x8000u);
    double worst = 0, scale = 1;
    for (const htx::render::Vec4& p : world) {
      const auto a = clip(half.view_proj, p.x, p.y, p.z);
      const auto b = clip(sc.view_proj, q16(2 * cx) - p.x, p.y, q16(2 * cz) - p.z);
      for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(a[k] - b[k])), scale = std::max(scale, std::abs(b[k]));
    }
    EXPECT_LE(worst, 1e-4 * scale) << "the half turn is not the mirror image through the middle";
    for (uint32_t turn : {0x1000u, 0x5555u, 0xC000u}) {
      const render_app::SceneData t = console_app::turned_scene(sc, axis, turn);
      const auto a = clip(t.view_proj, q16(cx), q16(1.0), q16(cz));
      const auto b = clip(sc.view_proj, q16(cx), q16(1.0), q16(cz));
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[k], b[k], 1e-4 * scale) << turn;
    }
  }
}

TEST(SystemRender, SocConfigIsTheIcebreakerRasterUnit) {
  const htx::ModelConfig cfg = htx::rtl_config("icebreaker");
  const htx::fw::RecordFormat f = cfg.record_format();
  EXPECT_EQ(render_app::kRecordFormat.xy_int_bits, f.xy_int_bits);
  EXPECT_EQ(render_app::kRecordFormat.z_bits, f.z_bits);
  EXPECT_EQ(render_app::kRecordFormat.q_bits, f.q_bits);
  EXPECT_EQ(render_app::kRecordFormat.uv_int_bits, f.uv_int_bits);
  const htx::fw::AutoConfig a = htx::fw::auto_config_of(cfg);
  EXPECT_TRUE(render_app::kAutoConfig == a) << "AUTO's configuration";
  EXPECT_EQ(render_app::kAutoTolerance, htx::render::kOne / 16);
}

TEST(SystemRender, FirmwareFrameOnTheSocEqualsTheCosimFrame) {
  const std::filesystem::path png = std::filesystem::path(::testing::TempDir()) / "htx_render_system_test.png";
  std::filesystem::remove(png);
  // render_cube: the render firmware's image that draws only the cube (render draws floor first).
  const auto r = htx::test::run_program({HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/render_cube.elf", "--max-cycles",
                                         "50000000", "--json", "--frame", png.string()},
                                        120s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const auto report = parse_report(r.out);
  ASSERT_EQ(report.size(), 1u) << r.out;
  ASSERT_TRUE(report.count("cube")) << r.out;
  const auto json = htx::test::last_json_line(r.out);
  EXPECT_EQ(json.at("reason"), "exit");

  const CosimFrame cube = cosim_frame("cube");
  const std::string want = hex8(crc32_bitwise(cube.color));
  const auto& fw = report.at("cube").fields;
  EXPECT_EQ(fw.at("crc32"), want) << "the firmware's checksum of its cube frame";
  EXPECT_EQ(fw.at("sent"), std::to_string(cube.sent));
  // The cube's frame is in the colour window the harness reads at exit.
  EXPECT_EQ(json.at("frame_crc32"), want) << "htx sim's frame_crc32";

  // --frame wrote that frame as a PNG (RGB565 expanded by bit replication).
  const htx::Image img = htx::load_image(png.string());
  ASSERT_EQ(img.width, render_app::kWidth);
  ASSERT_EQ(img.height, render_app::kHeight);
  EXPECT_EQ(img.rgba, htx::image_from_rgb565(img.width, img.height, cube.color).rgba);

  std::printf("SoC render cube: %s cycles/vertex (geometry), frame %s CPU cycles, raster %s cycles, crc32 %s\n",
              fw.at("geometry_cycles_per_vertex").c_str(), fw.at("frame_cycles").c_str(),
              fw.at("raster_cycles").c_str(), fw.at("crc32").c_str());
  std::printf("cosim cube: raster %u cycles, crc32 %s\nwhole run: %s\n", cube.raster_busy, want.c_str(),
              json.dump().c_str());
}

// The firmware's compiled-in scene of that name, or nullptr.
const render_app::SceneData* compiled_in_scene(const char* name) {
  uint32_t n = 0;
  const render_app::SceneData* scenes = render_app::builtin_scenes(&n);
  const render_app::SceneData* s =
      std::find_if(scenes, scenes + n, [name](const render_app::SceneData& sc) { return std::strcmp(sc.name, name) == 0; });
  return s == scenes + n ? nullptr : s;
}

// The console firmware on `htx sim --uart stdio`, fed `script` (its lines as typed).
htx::test::RunResult run_console_script(const std::string& name, const std::string& script) {
  const std::string path = ::testing::TempDir() + "htx_console_" + name + "_" + std::to_string(getpid()) + ".txt";
  std::ofstream(path) << script;
  const auto r = htx::test::run_program(
      {"/bin/sh", "-c",
       std::string(HTX_BIN) + " sim --elf " HTX_FIRMWARE_DIR "/console.elf --uart stdio --max-cycles 100000000 < " +
           path},
      180s);
  std::filesystem::remove(path);
  return r;
}

// The console's `set filter` draws every triangle with that filter: its frames are the cosim
// frames drawn so (the cube's own filter is bilinear, so `nearest` gives another frame), `scene`
// gives the scene's own again, and the filter the SoC's texture unit does not build (trilinear,
// TEXTURE CAPS.FILTERS) is refused and leaves the setting as it was.
TEST(SystemRender, ConsoleFilterSettingDrawsTheCosimFrames) {
  const auto r = run_console_script("filter",
                                    "info\nset filter nearest\nrender cube\nset filter trilinear\nrender cube\n"
                                    "set filter scene\nrender cube\nset filter cubic\nquit\n");
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("; filters nearest bilinear\r\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: this GPU does not build the filter trilinear"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown filter (nearest, bilinear, trilinear, scene): cubic"), std::string::npos)
      << r.out;
  std::vector<std::string> crcs;  // of the three renders, in order
  for (size_t at = r.out.find("render cube method auto filter "); at != std::string::npos;
       at = r.out.find("render cube method auto filter ", at + 1)) {
    const size_t c = r.out.find("crc32 ", at);
    ASSERT_NE(c, std::string::npos) << r.out;
    crcs.push_back(r.out.substr(c + 6, 8));
  }
  ASSERT_EQ(crcs.size(), 3u) << r.out;
  const std::string nearest = hex8(crc32_bitwise(cosim_frame("cube", 0).color));
  const std::string own = hex8(crc32_bitwise(cosim_frame("cube").color));
  EXPECT_NE(nearest, own);
  EXPECT_EQ(crcs[0], nearest) << r.out;
  EXPECT_EQ(crcs[1], nearest) << "trilinear was refused: still nearest\n" << r.out;
  EXPECT_EQ(crcs[2], own) << r.out;
  EXPECT_NE(r.out.find("render cube method auto filter nearest"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("render cube method auto filter scene"), std::string::npos) << r.out;
}

// `render SCENE over`: drawn over the frame drawn last, its colour and depth kept; `hold`: not
// shown yet. The console's cube over its floor is the host's draw_scene of the floor and then of
// the cube without clearing, over the Verilated GPU; the screen keeps the boot page through a held
// render; bad words are refused.
TEST(SystemRender, ConsoleRenderOverDrawsOnTheLastFrame) {
  const auto r = run_console_script("over", "render floor hold\ninfo\nrender cube over\nrender cube\n"
                                            "render cube over over\nrender cube under\nquit\n");
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("page 0 of 3"), std::string::npos) << "the held floor is not shown\n" << r.out;
  std::vector<std::string> crcs;  // of the render lines, in order: floor held, cube over it, cube alone
  const std::regex render_line(R"(render (floor|cube) method [^\r\n]* crc32 ([0-9a-f]{8}))");
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), render_line); it != std::sregex_iterator(); ++it)
    crcs.push_back((*it)[2]);
  std::smatch skipped;  // AUTO's choices the floor's draw took without comparing
  ASSERT_TRUE(std::regex_search(r.out, skipped, std::regex(R"(render floor method auto [^\r\n]* auto_skipped (\d+) )")))
      << r.out;
  ASSERT_EQ(crcs.size(), 3u) << r.out;
  size_t usage = 0;
  for (size_t at = r.out.find("error: usage: render SCENE [over] [hold]"); at != std::string::npos;
       at = r.out.find("error: usage: render SCENE [over] [hold]", at + 1))
    ++usage;
  EXPECT_EQ(usage, 2u) << r.out;

  htx::hal::sim::GpuSimBus bus("icebreaker");
  htx::hal::sim::ScopedBus attach(bus);
  std::vector<uint32_t> image(render_app::kTextureTexels);
  ASSERT_EQ(render_app::upload_scene_texture(1000, image.data()), htx::render::kUploadOk);
  const render_app::SceneData* floor_scene = compiled_in_scene("floor");
  const render_app::SceneData* cube_scene = compiled_in_scene("cube");
  ASSERT_TRUE(floor_scene && cube_scene);
  render_app::DrawSettings settings;
  settings.time_geometry = false;
  const render_app::DrawResult floor = render_app::draw_scene(*floor_scene, settings);
  ASSERT_TRUE(floor.ok) << floor.error;
  EXPECT_EQ(crcs[0], hex8(floor.crc));
  EXPECT_EQ(skipped[1], std::to_string(floor.stats.auto_skipped));
  EXPECT_GT(floor.stats.auto_skipped, 100u) << "most of floor's small triangles (docs/auto.md)";
  settings.clear = false;
  const render_app::DrawResult over = render_app::draw_scene(*cube_scene, settings);
  ASSERT_TRUE(over.ok) << over.error;
  EXPECT_EQ(crcs[1], hex8(over.crc));
  settings.clear = true;
  const render_app::DrawResult alone = render_app::draw_scene(*cube_scene, settings);
  EXPECT_EQ(crcs[2], hex8(alone.crc));
  EXPECT_NE(crcs[1], crcs[2]);
}

// A console render that fails (an uploaded scene whose mesh asks for trilinear, which the SoC's
// texture unit does not build) leaves the last good render's frame and figures: `stats` reports
// that render, and `render cube over` draws onto its page (the cube over itself changes nothing),
// not onto a page the failed render chose. The upload's line ends with CR LF: the LF is not taken
// for a damaged packet (the console answers every packet with one Ack and sends no Nak), and a
// packet sent after the upload ended is skipped by the line reader.
TEST(SystemRender, AFailedConsoleRenderLeavesTheLastGoodFrame) {
  const render_app::SceneData* cube = compiled_in_scene("cube");
  ASSERT_NE(cube, nullptr);
  htx::render::Mesh trilinear = cube->meshes[0];
  trilinear.state.filter = 2;
  std::vector<uint8_t> scene(htx::render::packed_scene_size(&trilinear, 1));
  ASSERT_NE(htx::render::pack_scene(cube->view_proj, cube->cull_backfaces, &trilinear, 1, scene.data(), scene.size()),
            0u);
  char upload[64];
  std::snprintf(upload, sizeof upload, "upload %zu %08x\r\n", scene.size(), htx::fw::crc32(scene.data(), scene.size()));
  std::string script = std::string("render cube\n") + upload;
  size_t packets = 0;
  for (size_t at = 0; at < scene.size(); at += htx::fw::kPacketMaxPayload, ++packets) {
    std::string line(htx::fw::kPacketMaxLine, '\0');
    line.resize(htx::fw::packet_encode(htx::fw::kPacketSceneData, static_cast<uint8_t>(packets), scene.data() + at,
                                       std::min(htx::fw::kPacketMaxPayload, scene.size() - at),
                                       reinterpret_cast<uint8_t*>(line.data())));
    script += line;
  }
  // A packet after the upload has ended (a host that sent one again: its answer came late) is not
  // text: the line reader skips the frame, and the next command runs whole. This one's payload is
  // printable, so that read as text it would prefix the next command.
  const std::string printable = "quit now please";
  std::string late(htx::fw::kPacketMaxLine, '\0');
  late.resize(htx::fw::packet_encode(htx::fw::kPacketSceneData, static_cast<uint8_t>(packets - 1),
                                     reinterpret_cast<const uint8_t*>(printable.data()), printable.size(),
                                     reinterpret_cast<uint8_t*>(late.data())));
  script += late;
  script += "render upload\nstats\nrender cube over\nquit\n";
  const auto r = run_console_script("failed_render", script);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;

  size_t acks = 0, naks = 0;
  htx::fw::PacketDecoder decoder;
  for (char c : r.out) {
    htx::fw::Packet p;
    if (htx::fw::packet_feed(&decoder, static_cast<uint8_t>(c), &p) != htx::fw::kPacketReady) continue;
    acks += p.type == htx::fw::kPacketAck;
    naks += p.type == htx::fw::kPacketNak;
  }
  EXPECT_EQ(acks, packets);  // (the copy came after the upload: no answer)
  // Nothing but the render's own failure is an error: the copy's bytes made no line of their own.
  size_t errors = 0;
  for (size_t at = r.out.find("error: "); at != std::string::npos; at = r.out.find("error: ", at + 1)) ++errors;
  EXPECT_EQ(errors, 1u) << r.out;
  EXPECT_EQ(naks, 0u);
  EXPECT_NE(r.out.find("upload ok: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: render failed: a mesh's filter is one this GPU does not build"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("htx> stats\r\nscene cube busy "), std::string::npos) << r.out;
  std::vector<std::string> crcs;
  const std::regex render_line(R"(render cube method [^\r\n]* crc32 ([0-9a-f]{8}))");
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), render_line); it != std::sregex_iterator(); ++it)
    crcs.push_back((*it)[1]);
  ASSERT_EQ(crcs.size(), 2u) << r.out;
  EXPECT_EQ(crcs[1], crcs[0]) << "`render cube over` did not draw onto the cube's frame";
}

// draw_scene (the console's and the render firmware's draw) on the host over the Verilated
// icebreaker GPU: a filter set for a draw gives the cosim frame drawn with it and is not left in
// it, so the compiled-in scene keeps its own; a filter the texture unit does not build (trilinear
// here), set or a mesh's own, is refused before anything is drawn (the texture unit would sample
// it bilinear at level 0 without a word).
TEST(SystemRender, DrawSceneTakesASetFilterAndRefusesOneTheGpuLacks) {
  const std::string nearest = hex8(crc32_bitwise(cosim_frame("cube", 0).color));
  const std::string own = hex8(crc32_bitwise(cosim_frame("cube").color));
  htx::hal::sim::GpuSimBus bus("icebreaker");
  htx::hal::sim::ScopedBus attach(bus);
  std::vector<uint32_t> image(render_app::kTextureTexels);
  ASSERT_EQ(render_app::upload_scene_texture(1000, image.data()), htx::render::kUploadOk);
  const render_app::SceneData* cube = compiled_in_scene("cube");
  ASSERT_NE(cube, nullptr);
  ASSERT_EQ(cube->mesh_count, 1u);
  const uint8_t cube_filter = cube->meshes[0].state.filter;
  ASSERT_EQ(cube_filter, 1) << "the built-in cube is bilinear";

  render_app::DrawSettings settings;
  settings.time_geometry = false;
  settings.filter = 0;  // nearest
  render_app::DrawResult r = render_app::draw_scene(*cube, settings);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(hex8(r.crc), nearest);
  EXPECT_EQ(cube->meshes[0].state.filter, cube_filter) << "the set filter was left in the scene";

  settings.filter = 2;  // trilinear: not built by icebreaker's texture unit
  r = render_app::draw_scene(*cube, settings);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(std::string(r.error).find("does not build"), std::string::npos) << r.error;
  EXPECT_EQ(cube->meshes[0].state.filter, cube_filter);

  settings.filter = render_app::kSceneFilter;
  htx::render::Mesh trilinear_mesh = cube->meshes[0];
  trilinear_mesh.state.filter = 2;  // as an uploaded scene may ask
  render_app::SceneData trilinear_cube = *cube;
  trilinear_cube.meshes = &trilinear_mesh;
  r = render_app::draw_scene(trilinear_cube, settings);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(std::string(r.error).find("does not build"), std::string::npos) << r.error;

  r = render_app::draw_scene(*cube, settings);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(hex8(r.crc), own);
}

// `htx render SCENE --engine soc --out PNG --metrics JSON EXTRA...` and the metrics it wrote (null
// when it failed).
struct SocRender {
  htx::test::RunResult run;
  nlohmann::json metrics;
};
SocRender render_on_soc(const std::string& scene, const std::string& png, const std::string& metrics,
                        const std::vector<std::string>& extra = {}) {
  std::vector<std::string> argv = {HTX_BIN, "render", scene, "--engine", "soc", "--out", png, "--metrics", metrics};
  argv.insert(argv.end(), extra.begin(), extra.end());
  SocRender r{htx::test::run_program(argv, 180s), nullptr};
  if (r.run.status == 0) {
    std::ifstream in(metrics);
    r.metrics = nlohmann::json::parse(in);
  }
  return r;
}

// `htx render --engine soc`: the cube uploaded to the console firmware on the simulated SoC, drawn
// there with the scene's own method (RECIP_NR; the console's default is AUTO) and sent back, is the
// cosim frame drawn so (the scene's 64 x 64 checkerboard goes as its 32 x 32 level, the console's
// own texture, so the uploaded cube draws what the compiled-in one does), and its metrics carry the
// console's figures. `--engine board` through the pty of `htx sim --uart pty` (a board as far as
// htx can tell), with AUTO within 1/16 texel and nearest filtering, gives the cosim frame drawn so,
// with the transfers at 1 Mbaud (`--fast-baud`) and the board left at 115,200 baud afterwards.
// What the console cannot draw is refused before anything runs.
TEST(SystemRender, SocAndBoardEnginesDrawTheCosimFrame) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("htx_render_engines_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string soc_png = (dir / "soc.png").string(), board_png = (dir / "board.png").string(),
                    metrics = (dir / "soc.json").string();
  const SocRender rendered = render_on_soc("cube", soc_png, metrics);
  const htx::test::RunResult& soc = rendered.run;
  ASSERT_FALSE(soc.timed_out);
  ASSERT_EQ(soc.status, 0) << soc.out << soc.err;
  const CosimFrame cube = cosim_frame("cube", render_app::kSceneFilter, htx::render::kMethodRecipNr);
  const std::string want = hex8(crc32_bitwise(cube.color));
  EXPECT_NE(soc.out.find("crc32 " + want), std::string::npos) << soc.out;
  const htx::Image img = htx::load_image(soc_png);
  ASSERT_EQ(img.width, render_app::kWidth);
  ASSERT_EQ(img.height, render_app::kHeight);
  EXPECT_EQ(img.rgba, htx::image_from_rgb565(img.width, img.height, cube.color).rgba);
  const nlohmann::json& m = rendered.metrics;
  EXPECT_EQ(m.at("engine"), "soc");
  EXPECT_EQ(m.at("config"), "icebreaker");
  EXPECT_EQ(m.at("method"), "recip_nr");
  EXPECT_FALSE(m.contains("auto")) << m.dump();  // (no AUTO, so no choices to report)
  EXPECT_EQ(m.at("crc32"), want);
  EXPECT_EQ(m.at("sent"), cube.sent);
  EXPECT_GT(m.at("cycles").get<uint64_t>(), 0u);
  EXPECT_GT(m.at("cpu_frame_cycles").get<uint64_t>(), 0u);
  // Against ref on the console's background; the rest is the texture's smaller level and the
  // fixed-point pipeline (27 dB when written).
  EXPECT_GT(m.at("psnr_db").get<double>(), 20.0);
  // The texel errors, from the model drawing the console's own triangles (its frame is the one
  // sent, pixel for pixel), against ref with the console's 32 x 32 texture: RECIP_NR's error and
  // the firmware's fixed-point geometry (0.00052 texel when written), every textured pixel of ref
  // textured by the same mesh.
  EXPECT_EQ(m.at("probe"), "model");
  EXPECT_GT(m.at("compared_pixels").get<uint64_t>(), 5000u) << m.dump();  // 7,082 when written
  EXPECT_EQ(m.at("coverage_diff_pixels"), 0);
  EXPECT_EQ(m.at("surface_diff_pixels"), 0);
  EXPECT_GT(m.at("max_texel_error").get<double>(), 0.0);
  EXPECT_LT(m.at("max_texel_error").get<double>(), 1.0 / 256);

  {
    htx::test::Child sim({HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/console.elf", "--uart", "pty",
                          "--max-cycles", "2000000000"});
    ASSERT_TRUE(sim.read_until("\n", 30s));
    const std::string marker = "htx sim: UART on ";
    const size_t at = sim.output().find(marker);
    ASSERT_NE(at, std::string::npos) << sim.output();
    const std::string pty = sim.output().substr(at + marker.size(), sim.output().find('\n', at) - at - marker.size());
    const auto board =
        htx::test::run_program({HTX_BIN, "render", "cube", "--engine", "board", "--port", pty, "--method", "auto",
                                "--tolerance", "0.0625", "--filter", "nearest", "--fast-baud", "1000000", "--out",
                                board_png, "--metrics", (dir / "board.json").string()},
                               180s);
    EXPECT_EQ(board.status, 0) << board.out << board.err;
    // The methods AUTO chose among are the ones the console's `info` lists, so the model's frame
    // of its triangles is its frame; AUTO keeps the coordinates within 1/16 texel of the model's
    // geometry, the firmware's moves them by about a thousandth more.
    std::ifstream board_json(dir / "board.json");
    const nlohmann::json bm = nlohmann::json::parse(board_json);
    EXPECT_EQ(bm.at("probe"), "model") << board.err;
    // The console's render line says how many choices it skipped: none of the cube's six large ones.
    EXPECT_EQ(bm.at("auto").at("skipped"), 0) << bm.dump();
    EXPECT_TRUE(bm.at("max_texel_error").is_number() && bm.at("max_texel_error").get<double>() < 1.0 / 16 + 1.0 / 256)
        << bm.dump();
    EXPECT_NE(board.err.find("board: serial line back to 115200 baud"), std::string::npos) << board.err;
    const CosimFrame nearest = cosim_frame("cube", 0, htx::render::kMethodAuto);
    EXPECT_NE(nearest.color, cube.color);
    EXPECT_EQ(htx::load_image(board_png).rgba,
              htx::image_from_rgb565(render_app::kWidth, render_app::kHeight, nearest.color).rgba);
    // --fast-baud left the board at --baud's rate (the UART at 12 MHz / 104).
    const auto info = htx::test::run_program({HTX_BIN, "console", "--port", pty, "-c", "info", "-c", "quit"}, 60s);
    EXPECT_EQ(info.status, 0);
    EXPECT_NE(info.out.find("serial 115384 baud"), std::string::npos) << info.out;
    EXPECT_EQ(sim.wait(60s), 0) << sim.output();
  }

  const auto refused = [&](std::vector<std::string> extra, const std::string& why) {
    std::vector<std::string> argv = {HTX_BIN, "render", "cube", "--out", (dir / "no.png").string()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    const auto r = htx::test::run_program(argv, 60s);
    EXPECT_NE(r.status, 0) << r.out;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "no.png"));
  };
  refused({"--engine", "soc", "--size", "320x240"}, "draws the console's 160x120 screen only");
  refused({"--engine", "soc", "--config", "full"}, "draws on the SoC's GPU, icebreaker");
  refused({"--engine", "soc", "--tolerance", "0.3"}, "the console takes 1/N texel");
  refused({"--engine", "soc", "--method", "quadratic"}, "only the model builds it");
  refused({"--engine", "soc", "--firmware", (dir / "none.elf").string()}, "no console firmware at");
  refused({"--engine", "board"}, "needs --port");
  refused({"--engine", "model", "--port", "/dev/null"}, "--port is for --engine board");
  refused({"--engine", "model", "--fast-baud", "1000000"}, "--fast-baud is for --engine board");
  refused({"--engine", "soc", "--fast-baud", "1000000"}, "--fast-baud is for --engine board");
  // Refused by the console itself, after the SoC started: htx reports its error and stops the
  // SoC's run instead of waiting for it (SimOptions::stop; the run's own limit is hours away).
  refused({"--engine", "soc", "--filter", "trilinear"}, "console: set filter trilinear: error: this GPU does not "
                                                        "build the filter trilinear");
  std::filesystem::remove_all(dir);
}

// An uploaded scene keeps its own textured and Gouraud flags (the compiled-in ones are drawn
// textured): an OBJ triangle of one material colour and no texture, drawn by `--engine soc`, is
// the colour `ref` draws, not that colour modulated by the console's texture (22 dB against ref
// when it was); so is the cube with `--untextured`.
TEST(SystemRender, SocEngineDrawsAnUntexturedSceneUntextured) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("htx_render_untextured_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tri.mtl") << "newmtl red\nKd 0.9 0.2 0.1\n";
  std::ofstream(dir / "tri.obj") << "mtllib tri.mtl\nusemtl red\nv -1 -1 -3\nv 1 -1 -3\nv 0 1 -3\nf 1 2 3\n";
  const std::string metrics = (dir / "m.json").string();
  const SocRender tri = render_on_soc((dir / "tri.obj").string(), (dir / "tri.png").string(), metrics);
  ASSERT_EQ(tri.run.status, 0) << tri.run.out << tri.run.err;
  const nlohmann::json& m = tri.metrics;
  EXPECT_LE(m.at("max_channel_diff").get<int>(), 8) << m.dump();
  EXPECT_TRUE(m.at("psnr_db").is_null() || m.at("psnr_db").get<double>() > 40.0) << m.dump();
  const SocRender cube = render_on_soc("cube", (dir / "cube.png").string(), metrics, {"--untextured"});
  ASSERT_EQ(cube.run.status, 0) << cube.run.out << cube.run.err;
  const nlohmann::json& c = cube.metrics;
  EXPECT_LE(c.at("max_channel_diff").get<int>(), 8) << c.dump();
  EXPECT_EQ(cube.run.err.find("upload: texture"), std::string::npos) << "no texture is sent\n" << cube.run.err;
  std::filesystem::remove_all(dir);
}

// The console's own drawing of an uploaded payload, on the host over the Verilated icebreaker GPU:
// the whole packed scene unpacked in one piece (as one upload holds it, at most kMaxSceneMeshes
// meshes), each texture written into its slot, and draw_scene with the uploaded scene's own
// shading and the given method (the console's code, without the SoC, its CPU or the serial line).
struct ConsoleCosim {
  ConsoleCosim(const htx::ScenePayload& payload, uint8_t method)
      : scene_bytes(payload.scene), textures(payload.textures), meshes(render_app::kMaxSceneMeshes) {
    using namespace htx;
    render::UnpackedScene up;
    if (const char* why = render::unpack_scene(scene_bytes.data(), scene_bytes.size(), meshes.data(),
                                               render_app::kMaxSceneMeshes, render_app::kMaxMeshVertices, &up))
      throw std::runtime_error(std::string("unpack_scene: ") + why);
    scene = {"upload", meshes.data(), up.mesh_count, up.view_proj, up.cull_backfaces, true};
    settings.time_geometry = false;
    settings.method = method;
    uint32_t base = 0;
    for (size_t slot = 0; slot < textures.size(); ++slot) {
      render::UnpackedTexture t;
      if (const char* why =
              render::unpack_texture(textures[slot].data(), textures[slot].size(), render::kConsoleTextureTexels, &t))
        throw std::runtime_error(std::string("unpack_texture: ") + why);
      if (render::upload_texture_texels16(static_cast<uint32_t>(slot), base, t.log2_width, t.log2_height, t.format,
                                          t.texels, 1000) != render::kUploadOk)
        throw std::runtime_error("texture upload failed");
      base += hal::texture_chain_blocks(t.log2_width, t.log2_height);
      settings.textures[slot] = {t.log2_width, t.log2_height, true};
    }
  }
  // The frame the last draw_scene left.
  std::vector<uint16_t> frame() const {
    return htx::test::read_frame_through_hal(render_app::kWidth, render_app::kHeight, 0).color;
  }

  htx::hal::sim::GpuSimBus bus{"icebreaker"};
  htx::hal::sim::ScopedBus attach{bus};
  std::vector<uint8_t> scene_bytes;              // unpack_scene reads the meshes in place
  std::vector<std::vector<uint8_t>> textures;    // upload_texture_texels16 filters in place
  std::vector<htx::render::Mesh> meshes;
  render_app::SceneData scene{};
  render_app::DrawSettings settings;
};

// A scene with two textures (nearclip: a checkerboard floor and a striped wall, both 64 x 64)
// uploaded by `htx render --engine soc` goes with each texture into its own console slot and each
// mesh naming its slot, and is the frame the console's own code draws from that payload on the
// host over the Verilated GPU (the packed scene and textures unpacked, each texture written into
// its slot, draw_scene with the uploaded scene's own shading). Against ref it is within 20 dB
// (28.5 when written; 10.5 when the console held one texture and drew the wall with the floor's).
TEST(SystemRender, SocEngineDrawsEachMeshWithItsOwnTexture) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("htx_render_slots_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string png = (dir / "nearclip.png").string();
  const SocRender rendered = render_on_soc("nearclip", png, (dir / "m.json").string());
  ASSERT_EQ(rendered.run.status, 0) << rendered.run.out << rendered.run.err;
  EXPECT_NE(rendered.run.err.find("upload: texture 1 of 2060 bytes"), std::string::npos) << rendered.run.err;
  EXPECT_GT(rendered.metrics.at("psnr_db").get<double>(), 20.0) << rendered.metrics.dump();

  const htx::ScenePayload payload = htx::scene_payload("nearclip", "160x120", true);
  ASSERT_EQ(payload.textures.size(), 2u);
  ConsoleCosim cosim(payload, htx::render::kMethodRecipNr);  // the scene's own, as the soc engine sets it
  std::set<uint8_t> slots_named;
  for (uint32_t m = 0; m < cosim.scene.mesh_count; ++m)
    if (cosim.meshes[m].state.textured) slots_named.insert(cosim.meshes[m].state.texture);
  EXPECT_EQ(slots_named, (std::set<uint8_t>{0, 1}));
  render_app::DrawSettings settings = cosim.settings;
  const render_app::SceneData& sc = cosim.scene;
  const render_app::DrawResult r = render_app::draw_scene(sc, settings);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NE(rendered.run.out.find("crc32 " + hex8(r.crc)), std::string::npos) << rendered.run.out;
  EXPECT_EQ(htx::load_image(png).rgba,
            htx::image_from_rgb565(render_app::kWidth, render_app::kHeight, cosim.frame()).rgba);

  // Both slots given slot 0's texture (the console before slots): another frame.
  settings.textures[1].present = false;
  EXPECT_NE(hex8(render_app::draw_scene(sc, settings).crc), hex8(r.crc));
  // No texture in slot 0 either (an overwrite the texture unit failed): refused, not drawn.
  settings.textures[0].present = false;
  const render_app::DrawResult none = render_app::draw_scene(sc, settings);
  EXPECT_FALSE(none.ok);
  EXPECT_NE(std::string(none.error).find("hold no texture"), std::string::npos) << none.error;
  std::filesystem::remove_all(dir);
}

// A scene larger than the console's store (a tunnel of 8 rings, about 21 KB) goes in parts, each
// uploaded and drawn over the last (`render upload [over] [hold]`), and the frame is the one the
// console's code draws from the whole scene at once (ConsoleCosim: one draw_scene over every
// mesh): the depth and colour a part leaves are what the next part draws over.
TEST(SystemRender, SocEngineDrawsASceneLargerThanTheStoreInParts) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("htx_render_parts_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string spec = "tunnel:rings=8";
  const htx::ScenePayload payload = htx::scene_payload(spec, "160x120", true);
  ASSERT_GT(payload.scene.size(), htx::render::kConsoleSceneBytes);
  ASSERT_EQ(payload.parts.size(), 2u);
  const SocRender r = render_on_soc(spec, (dir / "t.png").string(), (dir / "m.json").string());
  ASSERT_EQ(r.run.status, 0) << r.run.out << r.run.err;
  EXPECT_NE(r.run.err.find("soc: render part 2 of 2 over the frame"), std::string::npos) << r.run.err;
  ConsoleCosim whole(payload, htx::render::kMethodRecipNr);
  const render_app::DrawResult once = render_app::draw_scene(whole.scene, whole.settings);
  ASSERT_TRUE(once.ok) << once.error;
  EXPECT_EQ(r.metrics.at("crc32"), hex8(once.crc));
  EXPECT_EQ(r.metrics.at("sent"), once.stats.sent) << "the parts' figures are summed";
  EXPECT_EQ(htx::load_image((dir / "t.png").string()).rgba,
            htx::image_from_rgb565(render_app::kWidth, render_app::kHeight, whole.frame()).rgba);
  // (A console that cleared for each part would leave the second part alone: not this frame.)
  std::filesystem::remove_all(dir);
}

// A mesh without triangles (slivers without its needles) is not sent: the console refuses an
// empty mesh, and `htx render slivers:needles=0 --engine soc` failed with `not a valid scene
// (empty mesh)` until 2026-12-06. Every packed mesh has triangles and comes from a scene mesh that
// has them; a scene with no triangles at all is refused before anything is sent.
TEST(SystemRender, UploadPayloadLeavesOutMeshesWithoutTriangles) {
  const htx::Scene scene = htx::make_builtin_scene("slivers:needles=0");
  ASSERT_TRUE(std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const htx::Mesh& m) { return m.triangles.empty(); }));
  const htx::ScenePayload payload = htx::scene_payload(scene, "slivers:needles=0", "160x120", true);
  ASSERT_FALSE(payload.source_mesh.empty());
  for (uint32_t source : payload.source_mesh) EXPECT_FALSE(scene.meshes.at(source).triangles.empty()) << source;
  std::vector<htx::render::Mesh> meshes(render_app::kMaxSceneMeshes);
  for (const std::vector<uint8_t>& part : payload.parts) {
    htx::render::UnpackedScene up;
    EXPECT_EQ(htx::render::unpack_scene(part.data(), part.size(), meshes.data(), render_app::kMaxSceneMeshes,
                                        render_app::kMaxMeshVertices, &up),
              nullptr);
  }
  htx::Scene empty = scene;
  for (htx::Mesh& m : empty.meshes) m.triangles.clear();
  try {
    htx::scene_payload(empty, "nothing", "160x120", true);
    ADD_FAILURE() << "a scene without triangles was packed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'nothing' has no triangles to send to the console"), std::string::npos)
        << e.what();
  }
}

// A scene whose coordinates the firmware's Q16.16 cannot hold (bigtri 100 times its default size)
// is refused before anything is sent, naming the scene and the limit.
TEST(SystemRender, UploadPayloadRefusesCoordinatesBeyondTheFirmwaresNumbers) {
  try {
    htx::scene_payload("bigtri:size=100000", "160x120", true);
    ADD_FAILURE() << "packed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'bigtri:size=100000' cannot go to the console: value -100000.000000 does "
                                         "not fit Q16.16 (the firmware's numbers: -32768 to 32767)"),
              std::string::npos)
        << e.what();
  }
  // Q16.16 holds 20,000, but the firmware takes positions below 2^14: refused before the upload too.
  try {
    htx::scene_payload("bigtri:size=20000", "160x120", true);
    ADD_FAILURE() << "packed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has a vertex coordinate of 16384 or more (2^14, the firmware's limit)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(htx::scene_payload("bigtri:size=16000", "160x120", true));
}

// A scene with more textures than the console's four slots: the first four (in the order the
// meshes first use them) go into slots 0..3 and each mesh names its own; the fifth is not sent,
// its meshes name slot 0, and the note says so. An untextured upload sends none.
TEST(SystemRender, UploadPayloadPutsFourTexturesInSlotsAndTheFifthOnSlotZero) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("htx_render_five_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream mtl(dir / "five.mtl");
  std::ofstream obj(dir / "five.obj");
  obj << "mtllib five.mtl\nvt 0 0\nvt 1 0\nvt 0 1\n";
  for (int k = 0; k < 5; ++k) {
    htx::Image img;
    img.width = img.height = 8;
    img.rgba.assign(8 * 8 * 4, static_cast<uint8_t>(40 * k + 10));
    htx::write_png((dir / ("t" + std::to_string(k) + ".png")).string(), img);
    mtl << "newmtl m" << k << "\nKd 1 1 1\nmap_Kd t" << k << ".png\n";
    // Triangle k uses material 4 - k (the loader's mesh order is read back below).
    obj << "v " << k << " 0 -3\nv " << k + 1 << " 0 -3\nv " << k << " 1 -3\n";
  }
  for (int k = 0; k < 5; ++k)
    obj << "usemtl m" << 4 - k << "\nf " << 3 * k + 1 << "/1 " << 3 * k + 2 << "/2 " << 3 * k + 3 << "/3\n";
  mtl.close();
  obj.close();
  const std::string spec = (dir / "five.obj").string();
  const htx::ScenePayload p = htx::scene_payload(spec, "160x120", true);
  ASSERT_EQ(p.textures.size(), htx::render::kConsoleTextureSlots);
  EXPECT_NE(p.note.find("the scene uses 5 textures and the console keeps 4; the meshes of the others draw with texture 0"), std::string::npos) << p.note;
  std::vector<htx::render::Mesh> meshes(render_app::kMaxSceneMeshes);
  htx::render::UnpackedScene up;
  std::vector<uint8_t> packed = p.scene;
  ASSERT_EQ(htx::render::unpack_scene(packed.data(), packed.size(), meshes.data(), render_app::kMaxSceneMeshes,
                                      render_app::kMaxMeshVertices, &up),
            nullptr);
  ASSERT_EQ(up.mesh_count, 5u);
  // Mesh m is the loaded scene's mesh m; the slot it names holds its texture's level 0 as RGB565,
  // the slots filled in the order of first use, and the texture used last is on slot 0 unsent.
  const htx::Scene scene = htx::load_scene(spec);
  ASSERT_EQ(scene.meshes.size(), 5u);
  std::vector<int> first_use;
  for (uint32_t m = 0; m < 5; ++m) {
    const int index = scene.meshes[m].state.texture;
    const bool sent = first_use.size() < 4;
    first_use.push_back(index);
    EXPECT_EQ(meshes[m].state.texture, sent ? m : 0u) << "mesh " << m;
    if (!sent) continue;
    const htx::Texture& want = scene.textures[static_cast<size_t>(index)];
    const uint32_t rgba8 = want.format == htx::TexFormat::RGBA8888
                               ? want.levels[0][0]
                               : htx::fw::decode_texel(static_cast<uint8_t>(want.format), want.levels[0][0]);
    htx::render::UnpackedTexture t;
    std::vector<uint8_t> tex = p.textures[m];
    ASSERT_EQ(htx::render::unpack_texture(tex.data(), tex.size(), htx::render::kConsoleTextureTexels, &t), nullptr);
    EXPECT_EQ(t.log2_width, 3);
    EXPECT_EQ(static_cast<uint32_t>(t.texels[0] | (t.texels[1] << 8)),
              htx::fw::encode_texel(htx::fw::kTexelRgb565, rgba8))
        << "slot " << m;
  }
  std::sort(first_use.begin(), first_use.end());
  EXPECT_EQ(std::unique(first_use.begin(), first_use.end()) - first_use.begin(), 5) << "five textures, one a mesh";
  EXPECT_TRUE(htx::scene_payload(spec, "160x120", true, htx::render::kMaxPackedMeshVertices, true).textures.empty());
  std::filesystem::remove_all(dir);
}

// A scene of more than 256 textures: the console's slots are picked by the Scene meshes' own
// texture indices, not render::TriState's byte, in which texture 256 read as texture 0, so the
// cube's texture 256 was sent as texture 0 and drawn with it.
TEST(SystemRender, UploadPayloadPicksTexturesPastTheFirst256ByTheirOwnIndex) {
  htx::Scene scene = htx::make_builtin_scene("cube");
  ASSERT_EQ(scene.textures.size(), 1u);
  const htx::Texture blue = htx::checkerboard_texture(htx::TexFormat::RGB565, 3, 1, {0, 0, 255, 255}, {0, 0, 255, 255});
  scene.textures.insert(scene.textures.begin(), 256, blue);  // the cube's texture is now index 256
  for (htx::Mesh& m : scene.meshes)
    if (m.state.textured) m.state.texture = 256;
  const htx::ScenePayload p = htx::scene_payload(scene, "cube", "160x120", true);
  ASSERT_EQ(p.textures.size(), 1u);
  ASSERT_EQ(p.slot_of_texture.size(), 257u);
  EXPECT_EQ(p.slot_of_texture[256], 0);
  htx::render::UnpackedTexture t;
  std::vector<uint8_t> tex = p.textures[0];
  ASSERT_EQ(htx::render::unpack_texture(tex.data(), tex.size(), htx::render::kConsoleTextureTexels, &t), nullptr);
  EXPECT_EQ(t.log2_width, 5) << "the cube's 64 x 64 checkerboard as its 32 x 32 level, not the 8 x 8 blue";
  const htx::Texture& cube = scene.textures[256];
  EXPECT_EQ(static_cast<uint32_t>(t.texels[0] | (t.texels[1] << 8)),
            htx::fw::encode_texel(htx::fw::kTexelRgb565, htx::fw::decode_texel(static_cast<uint8_t>(cube.format),
                                                                              cube.levels[1][0])));
}

// A mesh of more than 65536 vertices (an OBJ grid of 22,000 triangles, three vertices each, as
// the loader makes them) goes to the console split into parts: its whole form keeps 32-bit
// indices until split_meshes narrows each part's; `htx upload` refused it before ("mesh '' has
// more than 65536 vertices"). The form that is not split still refuses it, naming the mesh.
TEST(SystemRender, UploadPayloadSplitsAMeshOfMoreThan65536Vertices) {
  htx::Scene scene = htx::make_builtin_scene("cube");
  htx::Mesh grid;
  grid.state = scene.meshes.at(0).state;
  constexpr int kSide = 110, kTriangles = 22000;
  for (int t = 0; t < kTriangles; ++t) {
    const double x = (t / 2 % kSide) / static_cast<double>(kSide) - 0.5, y = (t / 2 / kSide) / static_cast<double>(kSide) - 0.5;
    const double d = 1.0 / kSide;
    const std::array<std::array<double, 2>, 3> corners =
        t % 2 ? std::array<std::array<double, 2>, 3>{{{x, y}, {x + d, y + d}, {x, y + d}}}
              : std::array<std::array<double, 2>, 3>{{{x, y}, {x + d, y}, {x + d, y + d}}};
    const uint32_t first = static_cast<uint32_t>(grid.vertices.size());
    for (const auto& c : corners) {
      htx::Vertex v;
      v.pos = {c[0], c[1], 0};
      v.s = c[0];
      v.t = c[1];
      grid.vertices.push_back(v);
    }
    grid.triangles.push_back({first, first + 1, first + 2});
  }
  scene.meshes = {grid};
  ASSERT_GT(scene.meshes[0].vertices.size(), 65536u);
  const htx::ScenePayload p = htx::scene_payload(scene, "grid", "160x120", true);
  std::vector<htx::render::Mesh> meshes(htx::render::kConsoleSceneMeshes);
  uint32_t triangles = 0;
  for (const std::vector<uint8_t>& part : p.parts) {
    htx::render::UnpackedScene up;
    ASSERT_EQ(htx::render::unpack_scene(part.data(), part.size(), meshes.data(), htx::render::kConsoleSceneMeshes,
                                        render_app::kMaxMeshVertices, &up),
              nullptr);
    // Each part's triangles are the whole mesh's, in order, their corners where they were.
    for (uint32_t m = 0; m < up.mesh_count; ++m)
      for (uint32_t k = 0; k < meshes[m].triangle_count; ++k, ++triangles) {
        ASSERT_LT(triangles, static_cast<uint32_t>(kTriangles));
        for (uint32_t c = 0; c < 3; ++c) {
          const htx::render::MeshVertex& got = meshes[m].vertices[meshes[m].indices[3 * k + c]];
          const htx::Vertex& want = grid.vertices[grid.triangles[triangles][c]];
          ASSERT_EQ(got.x, htx::host::to_q16(want.pos.x)) << "triangle " << triangles;
          ASSERT_EQ(got.y, htx::host::to_q16(want.pos.y)) << "triangle " << triangles;
        }
      }
  }
  EXPECT_EQ(triangles, static_cast<uint32_t>(kTriangles)) << "every triangle sent, once";
  for (uint32_t source : p.source_mesh) EXPECT_EQ(source, 0u);
  try {
    htx::host::to_render_scene(scene, 160, 120);
    ADD_FAILURE() << "a mesh of more than 65536 vertices in 16-bit indices";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("mesh 0 has more than 65536 vertices"), std::string::npos) << e.what();
  }
}

// The SoC model stops the GPU's clock while the GPU is idle (htx_soc_fabric, Sim only), which must
// change nothing: the same run with the clock free-running (--no-gpu-gate) ends in the same cycle
// with the same instruction count, the same frame, and the same firmware report, whose figures
// include the GPU's own counters read over the bus.
TEST(SystemRender, GatedGpuClockGivesTheSameRunAsAFreeOne) {
  const std::vector<std::string> base = {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/render_cube.elf",
                                         "--max-cycles", "50000000", "--json"};
  std::vector<std::string> free_args = base;
  free_args.push_back("--no-gpu-gate");
  const auto gated = htx::test::run_program(base, 120s);
  const auto free_run = htx::test::run_program(free_args, 120s);
  ASSERT_FALSE(gated.timed_out);
  ASSERT_FALSE(free_run.timed_out);
  ASSERT_EQ(gated.status, 0) << gated.out << gated.err;
  ASSERT_EQ(free_run.status, 0) << free_run.out << free_run.err;
  const auto g = htx::test::last_json_line(gated.out);
  const auto f = htx::test::last_json_line(free_run.out);
  for (const char* key : {"reason", "exit_code", "cycles", "instret", "frame_crc32"})
    EXPECT_EQ(g.at(key), f.at(key)) << key;
  const auto gr = parse_report(gated.out);
  const auto fr = parse_report(free_run.out);
  ASSERT_TRUE(gr.count("cube")) << gated.out;
  ASSERT_TRUE(fr.count("cube")) << free_run.out;
  EXPECT_EQ(gr.at("cube").fields, fr.at("cube").fields);
  std::printf("gated GPU clock: %.0f cycles/s; free-running: %.0f cycles/s (%s cycles)\n",
              g.at("cycles_per_second").get<double>(), f.at("cycles_per_second").get<double>(),
              g.at("cycles").dump().c_str());
}

}  // namespace
