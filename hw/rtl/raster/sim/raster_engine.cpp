// Engine `rtl` (docs/raster.md): encode exactly as render_model does, push the words through the
// FIFO register, wait for idle, read the memories back.
#include "htx/rtl/raster_engine.hpp"

#include <algorithm>
#include <cstdio>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "htx/fw/vertex_record.h"
#include "htx/model/names.hpp"
#include "htx/model/perspective.hpp"
#include "htx/rtl/raster_sim.hpp"
#include "htx_regs.h"

namespace htx {

namespace {

constexpr uint32_t off(size_t o) { return static_cast<uint32_t>(o); }
#define HTX_RASTER_OFF(reg) off(offsetof(HTX_RASTER_Type, reg))

// The RTL builds exactly the named configurations; every field that changes a bit of the frame
// must match.
void check_config(const ModelConfig& c) {
  const ModelConfig* named = nullptr;
  for (const std::string& n : model_config_names())
    if (c.name == n) named = &model_config(n);
  if (!named) throw std::invalid_argument("rtl engine: configuration '" + c.name + "' is not built (full, icebreaker)");
  const ModelConfig& n = *named;
  const bool same = c.xy_int_bits == n.xy_int_bits && c.z_bits == n.z_bits && c.q_bits == n.q_bits &&
                    c.uv_int_bits == n.uv_int_bits && c.grad_frac_bits == n.grad_frac_bits &&
                    c.recip_table_bits == n.recip_table_bits && c.recip_guard_bits == n.recip_guard_bits &&
                    c.recip_width == n.recip_width && c.setup_nr_steps == n.setup_nr_steps &&
                    c.methods == n.methods;
  if (c.perspective_color)
    throw std::invalid_argument(
        "rtl engine: perspective-correct Gouraud colour (perspective_color) is not built yet; render with it off");
  if (!same)
    throw std::invalid_argument("rtl engine: configuration '" + c.name +
                                "' differs from the built one in a width, table or method set");
}

fw::VertexIn to_vertex_in(const ScreenVertex& v) {
  fw::VertexIn in;
  in.x = v.x;
  in.y = v.y;
  in.z = v.z;
  in.w = v.w;
  in.u = v.u;
  in.v = v.v;
  in.r = v.r;
  in.g = v.g;
  in.b = v.b;
  in.a = v.a;
  return in;
}

uint32_t field(uint32_t value, uint32_t pos, uint32_t msk) { return (value << pos) & msk; }

}  // namespace

ModelConfig rtl_config(const std::string& name) {
  ModelConfig c = model_config(name);
  c.perspective_color = false;
  return c;
}

uint32_t pack_state_word(const TriState& s, Method m) {
  return field(static_cast<uint32_t>(m), RASTER_STATE_METHOD_Pos, RASTER_STATE_METHOD_Msk) |
         field(s.subdiv_n, RASTER_STATE_SUBDIV_N_Pos, RASTER_STATE_SUBDIV_N_Msk) |
         field(static_cast<uint32_t>(s.filter), RASTER_STATE_FILTER_Pos, RASTER_STATE_FILTER_Msk) |
         field(static_cast<uint32_t>(s.wrap_u), RASTER_STATE_WRAP_U_Pos, RASTER_STATE_WRAP_U_Msk) |
         field(static_cast<uint32_t>(s.wrap_v), RASTER_STATE_WRAP_V_Pos, RASTER_STATE_WRAP_V_Msk) |
         field(static_cast<uint32_t>(s.depth_func), RASTER_STATE_DEPTH_FUNC_Pos, RASTER_STATE_DEPTH_FUNC_Msk) |
         field(s.depth_write ? 1u : 0u, RASTER_STATE_DEPTH_WRITE_Pos, RASTER_STATE_DEPTH_WRITE_Msk) |
         field(s.textured ? 1u : 0u, RASTER_STATE_TEXTURED_Pos, RASTER_STATE_TEXTURED_Msk) |
         field(s.gouraud ? 1u : 0u, RASTER_STATE_GOURAUD_Pos, RASTER_STATE_GOURAUD_Msk) |
         field(static_cast<uint32_t>(s.combine), RASTER_STATE_COMBINE_Pos, RASTER_STATE_COMBINE_Msk) |
         field(static_cast<uint32_t>(s.texture), RASTER_STATE_TEXTURE_Pos, RASTER_STATE_TEXTURE_Msk);
}

uint64_t frame_mismatch_pixels(const Frame& a, const Frame& b) {
  if (a.width != b.width || a.height != b.height || a.color.size() != b.color.size() ||
      a.depth.size() != b.depth.size())
    throw std::invalid_argument("frame_mismatch_pixels: frames differ in size");
  uint64_t n = 0;
  for (size_t i = 0; i < a.color.size(); ++i) n += (a.color[i] != b.color[i]) || (a.depth[i] != b.depth[i]);
  return n;
}

Frame render_rtl(const ScreenScene& scene, const ModelConfig& cfg, RtlStats* stats) {
  cfg.validate();
  check_config(cfg);
  if (scene.width < 1 || scene.height < 1 || scene.width > 4096 || scene.height > 4096 ||
      static_cast<uint64_t>(scene.width) * static_cast<uint64_t>(scene.height) > rtl::RasterSim::kFbPixels)
    throw std::invalid_argument("rtl engine: frame " + std::to_string(scene.width) + "x" +
                                std::to_string(scene.height) + " exceeds the " +
                                std::to_string(rtl::RasterSim::kFbPixels) + "-pixel memories or 4096 per side");

  // Encode first, so a bad triangle is reported before any simulation.
  const fw::RecordFormat format = cfg.record_format();
  std::vector<uint32_t> words;
  uint64_t sent = 0;
  for (const ScreenTri& tri : scene.tris) {
    const TriState& st = tri.state;
    const Method method = st.method == Method::Auto ? model::auto_method(tri, cfg) : st.method;
    if (!cfg.has_method(method) || method == Method::Auto)
      throw std::invalid_argument("rtl engine: method " + method_name(method, st.subdiv_n) + " is not built");
    if ((method == Method::Subdiv || method == Method::Quadratic) && (st.subdiv_n < 2 || st.subdiv_n > 64))
      throw std::invalid_argument("rtl engine: subdiv_n " + std::to_string(st.subdiv_n) + " outside 2..64");
    if (st.textured)
      throw std::invalid_argument(
          "rtl engine: textured triangles need the texture unit, which this build does not have (render untextured)");
    const fw::VertexIn in[3] = {to_vertex_in(tri.v[0]), to_vertex_in(tri.v[1]), to_vertex_in(tri.v[2])};
    fw::TriangleRecord rec;
    const fw::EncodeStatus status = fw::encode_triangle(format, in, &rec);
    if (status == fw::kEncodeBadFormat) throw std::logic_error("rtl engine: bad record format");
    if (status != fw::kEncodeOk) continue;  // the firmware does not send it
    uint32_t packed[fw::kTriangleWords];
    fw::pack_triangle(rec, packed);
    words.push_back(pack_state_word(st, method));
    words.insert(words.end(), packed, packed + fw::kTriangleWords);
    ++sent;
  }

  rtl::RasterSim sim(cfg.name);
  const uint32_t z_max = (uint32_t{1} << cfg.z_bits) - 1;
  sim.write_reg(HTX_RASTER_OFF(FB_SIZE), (static_cast<uint32_t>(scene.width) << RASTER_FB_SIZE_WIDTH_Pos) |
                                             (static_cast<uint32_t>(scene.height) << RASTER_FB_SIZE_HEIGHT_Pos));
  sim.write_reg(HTX_RASTER_OFF(FB_STRIDE), static_cast<uint32_t>(scene.width));
  sim.write_reg(HTX_RASTER_OFF(CLEAR_COLOR), scene.clear_color);
  sim.write_reg(HTX_RASTER_OFF(CLEAR_DEPTH), std::min<uint32_t>(scene.clear_depth, 0xFFFFFFu));
  const uint64_t clear_start = sim.cycles();
  sim.write_reg(HTX_RASTER_OFF(CTRL),
                RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk | RASTER_CTRL_CLEAR_DEPTH_Msk);
  sim.wait_idle();
  const uint64_t clear_cycles = sim.cycles() - clear_start;
  sim.write_reg(HTX_RASTER_OFF(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_COUNTERS_RESET_Msk);

  const uint64_t feed_start = sim.cycles();
  sim.push_words(words);
  sim.wait_idle();
  const uint64_t feed_cycles = sim.cycles() - feed_start;

  RtlStats s;
  s.cycles = sim.read_reg(HTX_RASTER_OFF(CNT_BUSY));
  s.feed_cycles = feed_cycles;
  s.covered_pixels = sim.read_reg(HTX_RASTER_OFF(CNT_FRAGMENTS));
  s.pixels_written = sim.read_reg(HTX_RASTER_OFF(CNT_PIXELS));
  s.triangles = sim.read_reg(HTX_RASTER_OFF(CNT_TRIANGLES));
  s.triangles_sent = sent;
  s.setup_busy_cycles = sim.read_reg(HTX_RASTER_OFF(CNT_SETUP_BUSY));
  s.stall_input = sim.read_reg(HTX_RASTER_OFF(CNT_STALL_INPUT));
  s.stall_setup = sim.read_reg(HTX_RASTER_OFF(CNT_STALL_SETUP));
  s.stall_fragment = sim.read_reg(HTX_RASTER_OFF(CNT_STALL_FRAGMENT));
  s.clear_cycles = clear_cycles;
  s.px_per_clk = s.cycles ? static_cast<double>(s.covered_pixels) / static_cast<double>(s.cycles) : 0.0;
  s.setup_cycles_per_triangle =
      s.triangles ? static_cast<double>(s.setup_busy_cycles) / static_cast<double>(s.triangles) : 0.0;
  if (sim.read_reg(HTX_RASTER_OFF(STATUS)) & RASTER_STATUS_ERR_STATE_Msk)
    throw std::logic_error("rtl engine: the raster unit flagged a triangle state it does not build");

  Frame frame;
  frame.width = scene.width;
  frame.height = scene.height;
  const uint32_t n = static_cast<uint32_t>(scene.width) * static_cast<uint32_t>(scene.height);
  frame.color = sim.read_color(n);
  frame.depth = sim.read_depth(n);
  for (uint32_t& z : frame.depth) z &= z_max;
  frame.probe.assign(n, PixelProbe{});
  frame.counters.triangles = scene.tris.size();
  frame.counters.fragments = s.covered_pixels;
  frame.counters.pixels_written = s.pixels_written;
  frame.counters.cycles = s.cycles;
  if (stats) *stats = s;
  return frame;
}

}  // namespace htx
