// Engine `model`: encode -> setup -> traversal -> perspective method -> texture -> depth -> frame.
// Every value after the encoder is an integer of a documented width (docs/model.md).
#include "htx/model/model.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>

#include "htx/fw/vertex_record.h"
#include "htx/model/lod.hpp"
#include "htx/model/names.hpp"
#include "htx/model/perspective.hpp"
#include "htx/model/raster_setup.hpp"
#include "htx/model/recip.hpp"
#include "htx/model/sampler.hpp"

namespace htx {

namespace {

using model::i128;

constexpr int kMaxScreen = 4096;

// round(a * b / 255) for 8-bit a, b, as the combiner computes it.
uint8_t modulate8(unsigned a, unsigned b) {
  const unsigned x = a * b + 128;
  return static_cast<uint8_t>((x + (x >> 8)) >> 8);
}

uint16_t to_rgb565(Rgba8 c) {
  return static_cast<uint16_t>((quantise_channel(c.r, 5) << 11) | (quantise_channel(c.g, 6) << 5) |
                               quantise_channel(c.b, 5));
}

void check_state(const std::vector<Texture>& textures, const TriState& st, const ModelConfig& cfg, Method method) {
  if (!cfg.has_method(method))
    throw std::invalid_argument("method " + method_name(method, st.subdiv_n) + " is not built in configuration " +
                                cfg.name);
  if ((method == Method::Subdiv || method == Method::Quadratic) && (st.subdiv_n < 2 || st.subdiv_n > 64))
    throw std::invalid_argument("subdiv_n " + std::to_string(st.subdiv_n) + " outside 2..64");
  if (!st.textured) return;
  if (!cfg.has_filter(st.filter))
    throw std::invalid_argument("filter " + std::string(filter_name(st.filter)) + " is not built in configuration " +
                                cfg.name);
  if (st.texture < 0 || static_cast<size_t>(st.texture) >= textures.size())
    throw std::invalid_argument("triangle names missing texture " + std::to_string(st.texture));
  const Texture& tex = textures[static_cast<size_t>(st.texture)];
  if (!cfg.has_format(tex.format))
    throw std::invalid_argument("texture format " + std::string(tex_format_name(tex.format)) +
                                " is not built in configuration " + cfg.name);
  if (tex.log2_width < kMinTexLog2 || tex.log2_width > kMaxTexLog2 || tex.log2_height < kMinTexLog2 ||
      tex.log2_height > kMaxTexLog2 || tex.levels.size() < level_count(tex))
    throw std::invalid_argument("texture " + std::to_string(st.texture) + " has a bad size or mip chain");
}

// Everything after the encoder for one triangle: setup, traversal, perspective method, texture,
// depth and colour into `frame` (counters included, except the triangle count).
struct FrameContext {
  const std::vector<Texture>& textures;
  const ModelConfig& cfg;
  const model::Log2Unit& log2_unit;
  model::SpanCoords& span;
  Frame& frame;
};

void draw_record(const fw::TriangleRecord& rec, const TriState& st, Method method, int mesh, int tri,
                 FrameContext& fc) {
  const ModelConfig& cfg = fc.cfg;
  Frame& frame = fc.frame;
  Counters& cnt = frame.counters;
  model::SpanCoords& span = fc.span;
  const model::Log2Unit& log2_unit = fc.log2_unit;
  const unsigned tf = cfg.texcoord_frac_bits;
  const double coord_scale = 1.0 / static_cast<double>(int64_t{1} << tf);
  const double lod_scale = 1.0 / static_cast<double>(1 << cfg.lod_frac_bits);
  const Texture* tex = st.textured ? &fc.textures[static_cast<size_t>(st.texture)] : nullptr;
  const model::TriangleUnit unit(rec, st, cfg, frame.width, frame.height, &log2_unit,
                                 tex ? level_count(*tex) - 1 : 0);
  if (unit.empty()) return;
  cnt.cycles += unit.setup_cycles();
  const Rgba8 flat = unit.flat_color();

  for (int y = unit.y_lo(); y <= unit.y_hi(); ++y) {
    int x0 = 0, x1 = -1;
    if (!unit.span(y, &x0, &x1)) continue;
    unit.span_coords(y, x0, x1, method, &span);
    cnt.cycles += span.cycles;
    for (int x = x0; x <= x1; ++x) {
      const size_t k = static_cast<size_t>(x - x0);
      const size_t idx = static_cast<size_t>(y) * static_cast<size_t>(frame.width) + static_cast<size_t>(x);
      ++cnt.fragments;
      if (method == Method::DivFree) {
        const uint32_t steps = span.divfree_steps[k];
        cnt.divfree_steps_total += steps;
        cnt.divfree_steps_max = std::max<uint64_t>(cnt.divfree_steps_max, steps);
        cnt.divfree_cap_hits += span.divfree_capped[k];
        ++cnt.divfree_pixels;
      }
      const int64_t px = 256 * int64_t{x} + 128, py = 256 * int64_t{y} + 128;
      const uint32_t z = unit.depth_at(px, py);
      if (!depth_passes(st.depth_func, z, frame.depth[idx])) continue;
      if (st.depth_write) frame.depth[idx] = z;
      Rgba8 c = st.gouraud ? unit.color_at(px, py) : flat;
      if (tex) {
        model::SampleRequest req;
        req.coord = {span.u[k] + (int64_t{rec.u_offset} << tf), span.v[k] + (int64_t{rec.v_offset} << tf), tf};
        req.filter = st.filter;
        req.wrap_u = st.wrap_u;
        req.wrap_v = st.wrap_v;
        req.lod_frac_bits = cfg.lod_frac_bits;
        const int32_t lod = unit.lod_at(log2_unit, px, py, span.u[k], span.v[k]);
        const int32_t top = static_cast<int32_t>(level_count(*tex) - 1) << cfg.lod_frac_bits;
        req.lod = lod == INT32_MIN ? 0 : std::clamp(lod, 0, top);
        unsigned level = 0;
        const Rgba8 t = model::sample(*tex, req, &level);
        c = st.combine == Combine::Replace
                ? t
                : Rgba8{modulate8(t.r, c.r), modulate8(t.g, c.g), modulate8(t.b, c.b), modulate8(t.a, c.a)};
        PixelProbe& pr = frame.probe[idx];
        pr.covered = true;
        pr.u = static_cast<double>(req.coord.u) * coord_scale;
        pr.v = static_cast<double>(req.coord.v) * coord_scale;
        pr.level = static_cast<int>(level);
        pr.lod = lod == INT32_MIN ? -64.0 : static_cast<double>(lod) * lod_scale;
        pr.divfree_steps = method == Method::DivFree ? span.divfree_steps[k] : 0;
        pr.mesh = mesh;
        pr.tri = tri;
      } else {
        frame.probe[idx] = PixelProbe{};  // an untextured fragment hides what was sampled here
      }
      frame.color[idx] = to_rgb565(c);
      ++cnt.pixels_written;
    }
  }
}

Frame blank_frame(int width, int height, uint16_t clear_color, uint32_t clear_depth, const ModelConfig& cfg) {
  if (width < 1 || height < 1 || width > kMaxScreen || height > kMaxScreen)
    throw std::invalid_argument("scene size " + std::to_string(width) + "x" + std::to_string(height) +
                                " outside 1..4096");
  const size_t npix = static_cast<size_t>(width) * static_cast<size_t>(height);
  Frame frame;
  frame.width = width;
  frame.height = height;
  const uint32_t z_max = (uint32_t{1} << cfg.z_bits) - 1;
  frame.color.assign(npix, clear_color);
  frame.depth.assign(npix, std::min(clear_depth, z_max));
  frame.probe.assign(npix, PixelProbe{});
  return frame;
}

}  // namespace

Frame render_model(const ScreenScene& scene, const ModelConfig& cfg) {
  cfg.validate();
  Frame frame = blank_frame(scene.width, scene.height, scene.clear_color, scene.clear_depth, cfg);
  const fw::RecordFormat format = cfg.record_format();
  const model::Log2Unit log2_unit(cfg.lod_log_index_bits, cfg.lod_frac_bits + 2);
  model::SpanCoords span;
  FrameContext fc{scene.textures, cfg, log2_unit, span, frame};

  for (size_t i = 0; i < scene.tris.size(); ++i) {
    const ScreenTri& tri = scene.tris[i];
    ++frame.counters.triangles;
    const TriState& st = tri.state;
    const Method method = st.method == Method::Auto ? model::auto_method(tri, cfg) : st.method;
    check_state(scene.textures, st, cfg, method);
    fw::VertexIn in[3] = {to_vertex_in(tri.v[0]), to_vertex_in(tri.v[1]), to_vertex_in(tri.v[2])};
    fw::TriangleRecord rec;
    const fw::EncodeStatus status = fw::encode_triangle(format, in, &rec);
    if (status == fw::kEncodeBadFormat) throw std::logic_error("model configuration yields a bad record format");
    if (status != fw::kEncodeOk) {  // the firmware does not send it: draws nothing
      ++frame.counters.dropped;
      continue;
    }
    draw_record(rec, st, method, tri.mesh, static_cast<int>(i), fc);
  }
  return frame;
}

Frame render_model_records(const RecordScene& scene, const ModelConfig& cfg) {
  cfg.validate();
  Frame frame = blank_frame(scene.width, scene.height, scene.clear_color, scene.clear_depth, cfg);
  const model::Log2Unit log2_unit(cfg.lod_log_index_bits, cfg.lod_frac_bits + 2);
  model::SpanCoords span;
  FrameContext fc{scene.textures, cfg, log2_unit, span, frame};
  for (size_t i = 0; i < scene.tris.size(); ++i) {
    const RecordTriangle& tri = scene.tris[i];
    ++frame.counters.triangles;
    if (tri.state.method == Method::Auto)
      throw std::invalid_argument("render_model_records: a record's method must be resolved (not auto)");
    check_state(scene.textures, tri.state, cfg, tri.state.method);
    draw_record(tri.record, tri.state, tri.state.method, tri.mesh, static_cast<int>(i), fc);
  }
  return frame;
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

}  // namespace htx
