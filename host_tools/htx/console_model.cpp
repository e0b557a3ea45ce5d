#include "console_model.hpp"

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "htx/host/captured_triangles.hpp"
#include "htx/model/config.hpp"
#include "htx/model/model.hpp"
#include "htx/model/names.hpp"
#include "htx/model/texture.hpp"
#include "htx/render/scene_pack.h"
#include "htx/render/texture_pack.h"
#include "htx/render/tri_state.h"
#include "scene_render.hpp"
#include "soc_config.hpp"

namespace htx {

namespace {

// The console's settings for `draw` (its `set method`, `set tolerance` and `set filter`).
render_app::DrawSettings console_settings(const ConsoleDraw& draw) {
  render_app::DrawSettings s;
  s.time_geometry = false;
  s.checksum = false;
  if (draw.method == "auto") {
    s.method = render::kMethodAuto;
  } else {
    const MethodChoice m = parse_method(draw.method);
    if (m.method == Method::Auto || m.method == Method::Quadratic)
      throw std::runtime_error("the console has no method " + draw.method);
    s.method = static_cast<uint8_t>(m.method);  // Affine .. DivFree: the STATE word's numbers
    s.subdiv_n = static_cast<uint8_t>(m.subdiv_n);
  }
  s.auto_tolerance = render::kOne / draw.tolerance_denominator;  // as `set tolerance 1/N` does
  s.filter = draw.filter == "scene" ? render_app::kSceneFilter : static_cast<uint8_t>(parse_filter(draw.filter));
  return s;
}

// A texture as the model holds it, from 16-bit texels of `format` (0 RGB565, 1 RGBA4444): decoded
// to 8 bits a channel and encoded again, which gives the same texels, and the same mip chain the
// firmware's upload makes from them (both box-filter the decoded level above).
Texture model_texture(uint8_t format, uint8_t log2_w, uint8_t log2_h, const uint8_t* texels16) {
  const TexFormat f = format == 0 ? TexFormat::RGB565 : TexFormat::RGBA4444;
  const size_t n = size_t{1} << (log2_w + log2_h);
  std::vector<uint8_t> rgba(4 * n);
  for (size_t i = 0; i < n; ++i) {
    const Rgba8 c = decode_texel(f, static_cast<uint32_t>(texels16[2 * i] | (texels16[2 * i + 1] << 8)));
    rgba[4 * i] = c.r;
    rgba[4 * i + 1] = c.g;
    rgba[4 * i + 2] = c.b;
    rgba[4 * i + 3] = c.a;
  }
  return make_texture(f, log2_w, log2_h, rgba);
}

// The console's boot texture in slot 0 (soc_texture.hpp), RGB565 as it uploads it.
Texture boot_checkerboard() {
  std::vector<uint32_t> words(render_app::kTextureTexels);
  render_app::checker_texels(words.data());
  std::vector<uint8_t> rgba(4 * words.size());
  for (size_t i = 0; i < words.size(); ++i)
    for (size_t b = 0; b < 4; ++b) rgba[4 * i + b] = static_cast<uint8_t>(words[i] >> (8 * b));
  return make_texture(TexFormat::RGB565, render_app::kTextureLog2, render_app::kTextureLog2, rgba);
}

// The names of `info`'s list `list` as a bit set by their index in names.
uint32_t named_bits(const std::string& list, const char* const* names, uint32_t count) {
  std::istringstream words(list);
  uint32_t set = 0;
  for (std::string w; words >> w;)
    for (uint32_t i = 0; i < count; ++i)
      if (w == names[i]) set |= 1u << i;
  return set;
}

}  // namespace

ConsoleCaps console_caps(console::ConsoleClient& client) {
  // "screen 160x120 rgb565; methods affine subdiv ...; filters nearest bilinear", then the slots.
  const std::string info = client.command("info");
  const size_t m = info.find("; methods"), f = info.find("; filters", m == std::string::npos ? 0 : m);
  if (m == std::string::npos || f == std::string::npos)
    throw std::runtime_error("console: info lists no methods and filters: " + info.substr(0, info.find('\n')));
  ConsoleCaps c;
  c.methods_built = named_bits(info.substr(m + 9, f - m - 9), render::kMethodNames, render::kMethodNameCount);
  c.filters_built =
      named_bits(info.substr(f + 9, info.find('\n', f) - f - 9), render::kFilterNames, render::kFilterNameCount);
  const size_t t0 = info.find("texture 0: ");
  c.slot0_uploaded =
      t0 != std::string::npos && info.substr(t0, info.find('\n', t0) - t0).find("(uploaded)") != std::string::npos;
  return c;
}

ConsoleModel console_model_frame(const ConsoleDraw& draw, const ConsoleCaps& caps) {
  render_app::DrawSettings settings = console_settings(draw);
  RecordScene records;
  records.width = render_app::kWidth;
  records.height = render_app::kHeight;
  records.clear_color = render_app::kClearColor;
  records.clear_depth = render_app::kClearDepth;
  const std::vector<std::vector<uint8_t>>& sent = draw.payload.textures;
  std::vector<Texture> slots(render_app::kDrawTextureSlots);
  const bool slot0_unknown = caps.slot0_uploaded && (sent.empty() || sent[0].empty());
  for (size_t slot = 0; slot < slots.size(); ++slot) {
    if (slot >= sent.size() || sent[slot].empty()) {
      // Slot 0 keeps the boot texture; the plan sends a mesh whose slot holds none to slot 0.
      slots[slot] = slot == 0 ? boot_checkerboard() : slots[0];
      continue;
    }
    std::vector<uint8_t> bytes = sent[slot];
    render::UnpackedTexture t;
    if (const char* why = render::unpack_texture(bytes.data(), bytes.size(), render::kConsoleTextureTexels, &t))
      throw std::runtime_error(std::string("texture ") + std::to_string(slot) + ": " + why);
    slots[slot] = model_texture(t.format, t.log2_width, t.log2_height, t.texels);
    settings.textures[slot] = {t.log2_width, t.log2_height, true};
  }
  records.textures = slots;

  // Each part as the console draws it: unpacked, planned and run through the pipeline in turn,
  // over the last (its colour and depth kept), so the records follow one another in one frame.
  std::vector<render::Mesh> meshes(render_app::kMaxSceneMeshes), planned(render_app::kMaxSceneMeshes);
  std::vector<render::ClipVert> clip(render_app::kMaxMeshVertices);
  std::vector<render::ScreenVert> screen(render_app::kMaxMeshVertices);
  std::vector<uint8_t> codes(render_app::kMaxMeshVertices);
  std::vector<host::CapturedTriangle> tris;
  std::vector<int> tri_mesh;  // the Scene mesh of each triangle in tris
  render::DrawStats stats;    // over the parts
  uint32_t packed = 0;        // the payload's meshes before this part's
  for (const std::vector<uint8_t>& part : draw.payload.parts) {
    render::UnpackedScene up;
    if (const char* why = render::unpack_scene(part.data(), part.size(), meshes.data(), render_app::kMaxSceneMeshes,
                                               render_app::kMaxMeshVertices, &up))
      throw std::runtime_error(std::string("scene part: ") + why);
    const render_app::SceneData sc{"upload", meshes.data(), up.mesh_count, up.view_proj, up.cull_backfaces, true};
    render::FrameParams frame;
    if (const char* why = render_app::plan_draw(sc, settings, caps.methods_built, caps.filters_built, planned.data(), &frame))
      throw std::runtime_error(why);
    render::VertexCache cache{clip.data(), screen.data(), codes.data(), render_app::kMaxMeshVertices};
    for (uint32_t m = 0; m < sc.mesh_count; ++m, ++packed) {
      if (render::draw_mesh(frame, sc.view_proj, planned[m], &cache, host::capture_sink(&tris), &stats) !=
          render::kDrawOk)
        throw std::runtime_error("the pipeline refused mesh " + std::to_string(m));
      const uint32_t source = packed < draw.payload.source_mesh.size() ? draw.payload.source_mesh[packed] : packed;
      tri_mesh.resize(tris.size(), static_cast<int>(source));
    }
  }
  for (size_t i = 0; i < tris.size(); ++i) {
    const TriState st = host::from_state_word(tris[i].state_word);
    if (slot0_unknown && st.textured && st.texture == 0)
      throw std::runtime_error("texture slot 0 holds a texture uploaded before this draw, which htx has not got");
    records.tris.push_back({tris[i].record, st, tri_mesh[i]});
  }

  // The raster unit's configuration: rtl_config("icebreaker") (Gouraud colour linear in screen
  // space, as the RTL builds it), written out here because the board engine needs no RTL library.
  ModelConfig config = model_config("icebreaker");
  config.perspective_color = false;
  config.methods = caps.methods_built;
  config.filters = caps.filters_built;
  return {render_model_records(records, config), std::move(slots), stats.triangles, stats.sent};
}

std::string console_model_disagreement(const ConsoleModel& model, const ConsoleDrawn& drawn) {
  const std::string counts = std::to_string(model.triangles) + " triangles, " + std::to_string(model.sent) + " sent";
  const std::string console_counts =
      drawn.figures.at("triangles") + " triangles, " + drawn.figures.at("sent") + " sent";
  if (counts != console_counts) return "the host's pipeline made " + counts + ", the console's " + console_counts;
  const std::vector<uint16_t>& sent_pixels = drawn.frame.pixels;
  if (sent_pixels.size() != model.frame.color.size())
    return "the console sent " + std::to_string(sent_pixels.size()) + " pixels, the model drew " +
           std::to_string(model.frame.color.size());
  size_t differ = 0;
  for (size_t i = 0; i < sent_pixels.size(); ++i) differ += model.frame.color[i] != sent_pixels[i];
  if (differ != 0)
    return "the model's frame of the console's triangles differs from the console's at " + std::to_string(differ) +
           " pixels";
  return {};
}

}  // namespace htx
