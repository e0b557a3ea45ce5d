// Engine `rtl` (docs/raster.md, docs/gpu.md): encode exactly as render_model does, upload the
// textures through the texture memory window and their descriptors through TEXTURE, push the words
// through RASTER.FIFO of the Verilated GPU, wait for idle, read the memories back.
#include "htx/rtl/raster_engine.hpp"

#include <algorithm>
#include <cstdio>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "htx/fw/vertex_record.h"
#include "htx/model/model.hpp"
#include "htx/model/names.hpp"
#include "htx/model/perspective.hpp"
#include "htx/model/texture.hpp"
#include "htx/rtl/fifo_records.hpp"
#include "htx/rtl/gpu_sim.hpp"
#include "htx/rtl/texture_layout.hpp"
#include "htx_regs.h"

namespace htx {

namespace {

constexpr uint32_t off(size_t o) { return static_cast<uint32_t>(o); }
#define HTX_RASTER_REG(reg) (HTX_RASTER_BASE + off(offsetof(HTX_RASTER_Type, reg)))
#define HTX_TEXTURE_REG(reg) (HTX_TEXTURE_BASE + off(offsetof(HTX_TEXTURE_Type, reg)))

// Perspective methods the Verilated GPU builds (htx_gpu_full / htx_gpu_icebreaker `Methods`):
// AFFINE, SUBDIV, RECIP_LUT, RECIP_NR, DIVFREE in both configurations.
constexpr uint32_t kRtlMethods = 0x1F;
// The Verilated GPU that renders a configuration: an `icebreaker` configuration that names no
// methods beyond the board's (icebreaker_board_methods) is rendered on the GPU built with only
// those, the design the synthesis report measures.
std::string gpu_variant(const ModelConfig& c) {
  if (config_base_name(c) == "icebreaker" && (c.methods & ~icebreaker_board_methods()) == 0) return "icebreaker_board";
  return c.name;
}

// The RTL builds exactly the named configurations; every field that changes a bit of the frame
// must match, and the methods must be ones it builds.
void check_config(const ModelConfig& c) {
  const ModelConfig* named = nullptr;
  for (const std::string& n : model_config_names())
    if (config_base_name(c) == n) named = &model_config(n);
  if (!named) throw std::invalid_argument("rtl engine: configuration '" + c.name + "' is not built (full, icebreaker)");
  const ModelConfig& n = *named;
  const bool same = c.xy_int_bits == n.xy_int_bits && c.z_bits == n.z_bits && c.q_bits == n.q_bits &&
                    c.uv_int_bits == n.uv_int_bits && c.grad_frac_bits == n.grad_frac_bits &&
                    c.recip_table_bits == n.recip_table_bits && c.recip_guard_bits == n.recip_guard_bits &&
                    c.recip_width == n.recip_width && c.setup_nr_steps == n.setup_nr_steps &&
                    c.pixel_nr_steps == n.pixel_nr_steps && c.texcoord_frac_bits == n.texcoord_frac_bits &&
                    c.lod_frac_bits == n.lod_frac_bits && c.lod_log_index_bits == n.lod_log_index_bits &&
                    c.lod_grad_bits == n.lod_grad_bits && c.filters == n.filters && c.formats == n.formats &&
                    c.divfree_frac_bits == n.divfree_frac_bits && c.divfree_cap == n.divfree_cap &&
                    c.perspective_color == n.perspective_color;
  if (c.methods & ~kRtlMethods)
    throw std::invalid_argument("rtl engine: the configuration names methods the RTL does not build (it builds "
                                "affine, subdiv, recip_lut, recip_nr, divfree)");
  if (!same)
    throw std::invalid_argument("rtl engine: configuration '" + c.name +
                                "' differs from the built one in a width, table, filter or format set, or in "
                                "perspective-correct colour");
}

// What the model refuses for a textured triangle, the RTL refuses too (the same messages' sense).
void check_texture_state(const std::vector<Texture>& textures, const TriState& st, const ModelConfig& cfg) {
  if (!cfg.has_filter(st.filter))
    throw std::invalid_argument("rtl engine: filter " + std::string(filter_name(st.filter)) + " is not built in '" +
                                cfg.name + "'");
  if (st.texture < 0 || static_cast<size_t>(st.texture) >= textures.size())
    throw std::invalid_argument("rtl engine: triangle names missing texture " + std::to_string(st.texture));
  const Texture& tex = textures[static_cast<size_t>(st.texture)];
  if (!cfg.has_format(tex.format))
    throw std::invalid_argument("rtl engine: texture format " + std::string(tex_format_name(tex.format)) +
                                " is not built in '" + cfg.name + "'");
  if (tex.log2_width < kMinTexLog2 || tex.log2_width > kMaxTexLog2 || tex.log2_height < kMinTexLog2 ||
      tex.log2_height > kMaxTexLog2 || tex.levels.size() != level_count(tex))
    throw std::invalid_argument("rtl engine: texture " + std::to_string(st.texture) + " has a bad size or mip chain");
  for (unsigned l = 0; l < tex.levels.size(); ++l)
    if (tex.levels[l].size() != (size_t{1} << (level_log2_width(tex, l) + level_log2_height(tex, l))))
      throw std::invalid_argument("rtl engine: texture " + std::to_string(st.texture) + " level " +
                                  std::to_string(l) + " has the wrong texel count");
}

// Uploads every texture a textured triangle names into slot = its index, the chains one after the
// other from block 0, each level through the texture memory window and the descriptor through
// TEXTURE.TEXn. Throws when an index exceeds the slots built or the chains exceed the memory.
void upload_textures(rtl::GpuSim& sim, const ScreenScene& scene) {
  std::vector<bool> used(scene.textures.size(), false);
  for (const ScreenTri& tri : scene.tris)
    if (tri.state.textured) used[static_cast<size_t>(tri.state.texture)] = true;
  const uint32_t caps = sim.read_reg(HTX_TEXTURE_REG(CAPS));
  const uint32_t slots = (caps & TEXTURE_CAPS_SLOTS_Msk) >> TEXTURE_CAPS_SLOTS_Pos;
  std::vector<std::pair<uint32_t, uint32_t>> words;
  std::vector<std::pair<uint32_t, uint32_t>> descriptors;
  uint32_t base = 0;
  for (size_t t = 0; t < used.size(); ++t) {
    if (!used[t]) continue;
    if (t >= slots)
      throw std::invalid_argument("rtl engine: texture " + std::to_string(t) + " needs slot " + std::to_string(t) +
                                  ", but this configuration builds " + std::to_string(slots) + " texture slots");
    const Texture& tex = scene.textures[t];
    const uint32_t blocks = rtl::texture_chain_blocks(tex);
    if (uint64_t{base} + blocks > sim.texture_blocks() || base > (TEXTURE_TEX0_BASE_Msk >> TEXTURE_TEX0_BASE_Pos))
      throw std::invalid_argument("rtl engine: the scene's textures need more than the " +
                                  std::to_string(sim.texture_blocks() * 4) + " texels of texture memory");
    rtl::append_texture_words(tex, base, rtl::GpuSim::kTextureWindow, words);
    descriptors.emplace_back(HTX_TEXTURE_REG(TEX0) + 4 * static_cast<uint32_t>(t), rtl::texture_descriptor(tex, base));
    base += blocks;
  }
  if (sim.mem_write_burst(words) != 0)
    throw std::logic_error("rtl engine: the texture memory refused a texel write inside its range");
  for (const auto& [addr, value] : descriptors) sim.write_reg(addr, value);
}

uint32_t field(uint32_t value, uint32_t pos, uint32_t msk) { return (value << pos) & msk; }

}  // namespace

ModelConfig rtl_config(const std::string& name) {
  ModelConfig c = model_config(name);
  c.methods &= kRtlMethods;
  return c;
}

ModelConfig rtl_board_config() { return icebreaker_board_config(rtl_config("icebreaker")); }

uint32_t pack_state_word(const TriState& s, Method m, unsigned divfree_top) {
  // DIVFREE has no subdivision length: its SUBDIV_N field carries the texture's last mip level.
  const uint32_t n = m == Method::DivFree ? divfree_top : s.subdiv_n;
  return field(static_cast<uint32_t>(m), RASTER_STATE_METHOD_Pos, RASTER_STATE_METHOD_Msk) |
         field(n, RASTER_STATE_SUBDIV_N_Pos, RASTER_STATE_SUBDIV_N_Msk) |
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
      static_cast<uint64_t>(scene.width) * static_cast<uint64_t>(scene.height) > rtl::GpuSim::kFbPixels)
    throw std::invalid_argument("rtl engine: frame " + std::to_string(scene.width) + "x" +
                                std::to_string(scene.height) + " exceeds the " +
                                std::to_string(rtl::GpuSim::kFbPixels) + "-pixel memories or 4096 per side");

  // Encode first, so a bad triangle is reported before any simulation.
  const fw::RecordFormat format = cfg.record_format();
  struct Encoded {
    uint32_t state_word;
    fw::TriangleRecord rec;
  };
  std::vector<Encoded> encoded;
  for (const ScreenTri& tri : scene.tris) {
    const TriState& st = tri.state;
    const Method method = st.method == Method::Auto ? model::auto_method(tri, cfg) : st.method;
    if (!cfg.has_method(method) || method == Method::Auto)
      throw std::invalid_argument("rtl engine: method " + method_name(method, st.subdiv_n) +
                                  " is not built in configuration " + cfg.name);
    if ((method == Method::Subdiv || method == Method::Quadratic) && (st.subdiv_n < 2 || st.subdiv_n > 64))
      throw std::invalid_argument("rtl engine: subdiv_n " + std::to_string(st.subdiv_n) + " outside 2..64");
    if (st.textured) check_texture_state(scene.textures, st, cfg);
    const fw::VertexIn in[3] = {to_vertex_in(tri.v[0]), to_vertex_in(tri.v[1]), to_vertex_in(tri.v[2])};
    Encoded e;
    const fw::EncodeStatus status = fw::encode_triangle(format, in, &e.rec);
    if (status == fw::kEncodeBadFormat) throw std::logic_error("rtl engine: bad record format");
    if (status != fw::kEncodeOk) continue;  // the firmware does not send it
    // DIVFREE's level choice (bilinear, trilinear) needs the texture's last mip level.
    const unsigned top = st.textured ? level_count(scene.textures[static_cast<size_t>(st.texture)]) - 1 : 0;
    e.state_word = pack_state_word(st, method, top);
    encoded.push_back(e);
  }

  rtl::GpuSim sim(gpu_variant(cfg));
  // The metrics come from the unit's counters, and every method the scene may use must be built.
  const uint32_t caps = sim.read_reg(HTX_RASTER_REG(CAPS));
  if (!(caps & RASTER_CAPS_COUNTERS_Msk))
    throw std::logic_error("rtl engine: the Verilated GPU has no raster counters (CAPS.COUNTERS = 0)");
  if (cfg.methods & ~((caps & RASTER_CAPS_METHODS_Msk) >> RASTER_CAPS_METHODS_Pos))
    throw std::logic_error("rtl engine: the Verilated GPU does not build every method of the configuration");
  // Vertex records, or (CAPS.FW_SETUP) plane records set up as the firmware does.
  const rtl::FifoRecords records(cfg, caps, scene.width, scene.height);
  std::vector<uint32_t> words;
  uint64_t sent = 0;
  for (const Encoded& e : encoded) sent += records.append(&words, e.state_word, e.rec) ? 1 : 0;
  upload_textures(sim, scene);
  const uint32_t z_max = (uint32_t{1} << cfg.z_bits) - 1;
  sim.write_reg(HTX_RASTER_REG(FB_SIZE), (static_cast<uint32_t>(scene.width) << RASTER_FB_SIZE_WIDTH_Pos) |
                                             (static_cast<uint32_t>(scene.height) << RASTER_FB_SIZE_HEIGHT_Pos));
  sim.write_reg(HTX_RASTER_REG(FB_STRIDE), static_cast<uint32_t>(scene.width));
  sim.write_reg(HTX_RASTER_REG(CLEAR_COLOR), scene.clear_color);
  sim.write_reg(HTX_RASTER_REG(CLEAR_DEPTH), std::min<uint32_t>(scene.clear_depth, 0xFFFFFFu));
  const uint64_t clear_start = sim.cycles();
  sim.write_reg(HTX_RASTER_REG(CTRL),
                RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_CLEAR_COLOR_Msk | RASTER_CTRL_CLEAR_DEPTH_Msk);
  sim.wait_idle();
  const uint64_t clear_cycles = sim.cycles() - clear_start;
  sim.write_reg(HTX_RASTER_REG(CTRL), RASTER_CTRL_ENABLE_Msk | RASTER_CTRL_COUNTERS_RESET_Msk);

  const uint64_t feed_start = sim.cycles();
  sim.push_words(words);
  sim.wait_idle();
  const uint64_t feed_cycles = sim.cycles() - feed_start;

  RtlStats s;
  s.cycles = sim.read_reg(HTX_RASTER_REG(CNT_BUSY));
  s.feed_cycles = feed_cycles;
  s.covered_pixels = sim.read_reg(HTX_RASTER_REG(CNT_FRAGMENTS));
  s.pixels_written = sim.read_reg(HTX_RASTER_REG(CNT_PIXELS));
  s.triangles = sim.read_reg(HTX_RASTER_REG(CNT_TRIANGLES));
  s.triangles_encoded = encoded.size();
  s.triangles_sent = sent;
  s.setup_busy_cycles = sim.read_reg(HTX_RASTER_REG(CNT_SETUP_BUSY));
  s.stall_input = sim.read_reg(HTX_RASTER_REG(CNT_STALL_INPUT));
  s.stall_setup = sim.read_reg(HTX_RASTER_REG(CNT_STALL_SETUP));
  s.stall_fragment = sim.read_reg(HTX_RASTER_REG(CNT_STALL_FRAGMENT));
  s.clear_cycles = clear_cycles;
  s.divfree_steps = sim.read_reg(HTX_RASTER_REG(CNT_DIVFREE_STEPS));
  s.px_per_clk = s.cycles ? static_cast<double>(s.covered_pixels) / static_cast<double>(s.cycles) : 0.0;
  s.setup_cycles_per_triangle =
      s.triangles ? static_cast<double>(s.setup_busy_cycles) / static_cast<double>(s.triangles) : 0.0;
  if (sim.read_reg(HTX_RASTER_REG(STATUS)) & RASTER_STATUS_ERR_STATE_Msk)
    throw std::logic_error("rtl engine: the raster unit flagged a triangle state it does not build");
  if (sim.read_reg(HTX_TEXTURE_REG(STATUS)) & (TEXTURE_STATUS_ERR_FORMAT_Msk | TEXTURE_STATUS_ERR_FILTER_Msk))
    throw std::logic_error("rtl engine: the texture unit flagged a format or filter it does not build");

  Frame frame;
  frame.width = scene.width;
  frame.height = scene.height;
  const uint32_t n = static_cast<uint32_t>(scene.width) * static_cast<uint32_t>(scene.height);
  frame.color = sim.read_color(n);
  frame.depth = sim.read_depth(n);
  for (uint32_t& z : frame.depth) z &= z_max;
  frame.probe.assign(n, PixelProbe{});
  frame.counters.triangles = scene.tris.size();
  frame.counters.dropped = scene.tris.size() - encoded.size();  // the encoder's refusals, not sent
  frame.counters.fragments = s.covered_pixels;
  frame.counters.pixels_written = s.pixels_written;
  frame.counters.cycles = s.cycles;
  frame.counters.divfree_steps_total = s.divfree_steps;
  if (stats) *stats = s;
  return frame;
}

}  // namespace htx
