#include "console_render.hpp"

#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>


namespace htx {

namespace {

// A command whose whole answer must be `ok`.
void set(console::ConsoleClient& client, const std::string& what, const std::string& value) {
  const std::string line = "set " + what + " " + value;
  const std::string out = client.command(line);
  if (out != "ok\n") throw std::runtime_error("console: " + line + ": " + out.substr(0, out.find('\n')));
}

// "render upload method M filter F triangles T ... crc32 C": the pairs after the scene's name.
std::map<std::string, std::string> render_figures(const std::string& out) {
  const std::string head = "render upload ";
  if (out.compare(0, head.size(), head) != 0)
    throw std::runtime_error("console: render upload: " + out.substr(0, out.find('\n')));
  std::istringstream words(out.substr(head.size(), out.find('\n') - head.size()));
  std::map<std::string, std::string> f;
  std::string key, value;
  while (words >> key >> value) f[key] = value;
  for (const char* k : {"triangles", "sent", "frame_cycles", "raster_cycles", "fragments", "crc32"})
    if (!f.count(k)) throw std::runtime_error(std::string("console: render upload printed no ") + k + ": " + out);
  return f;
}

// Two of the render line's counts added; `-` (a GPU without counters) stays `-`.
std::string sum_figure(const std::string& a, const std::string& b) {
  if (a == "-" || b == "-") return "-";
  return std::to_string(std::stoull(a) + std::stoull(b));
}

}  // namespace

ConsoleDrawn draw_on_console(console::ConsoleClient& client, const ConsoleDraw& draw) {
  const ScenePayload& payload = draw.payload;
  const auto step = [&draw](const std::string& what) {
    if (draw.on_step) draw.on_step(what);
  };
  ConsoleDrawn d;
  d.parts = payload.parts.size();
  if (d.parts == 0) throw std::logic_error("draw_on_console: a payload without scene parts");
  if (!payload.note.empty()) step(payload.note);
  for (size_t k = 0; k < d.parts; ++k) {
    const std::string part = d.parts > 1 ? " part " + std::to_string(k + 1) + " of " + std::to_string(d.parts) : "";
    // The scene first: a refused scene leaves the console's textures as they were too.
    step("upload: scene" + part + " of " + std::to_string(payload.parts[k].size()) + " bytes");
    client.upload(payload.parts[k]);
    if (k == 0) {
      for (size_t slot = 0; slot < payload.textures.size(); ++slot) {
        if (payload.textures[slot].empty()) continue;
        step("upload: texture " + std::to_string(slot) + " of " + std::to_string(payload.textures[slot].size()) +
             " bytes");
        client.upload(payload.textures[slot], {}, console::ConsoleClient::Payload::kTexture,
                      static_cast<unsigned>(slot));
      }
      const std::string tolerance = "1/" + std::to_string(draw.tolerance_denominator);
      step("set method " + draw.method + ", tolerance " + tolerance + ", filter " + draw.filter + "; render");
      set(client, "method", draw.method);
      set(client, "tolerance", tolerance);
      set(client, "filter", draw.filter);
    } else {
      step("render" + part + " over the frame");
    }
    // Each part over the last, the frame shown once the last is drawn.
    const std::string command =
        std::string("render upload") + (k > 0 ? " over" : "") + (k + 1 < d.parts ? " hold" : "");
    std::map<std::string, std::string> f = render_figures(client.command(command));
    if (k == 0) {
      d.figures = f;
      continue;
    }
    for (const char* key : {"triangles", "sent", "dropped", "auto_skipped", "frame_cycles", "raster_cycles", "fragments"})
      if (d.figures.count(key)) d.figures[key] = sum_figure(d.figures[key], f[key]);
    d.figures["crc32"] = f["crc32"];
  }
  if (client.resent_packets() > 0)
    step("upload: " + std::to_string(client.resent_packets()) + " packets sent again (the console missed them)");
  step("grab: the frame");
  d.frame = client.grab();
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x", d.frame.crc32);
  if (d.figures.at("crc32") != crc)
    throw std::runtime_error("console: the frame sent has CRC-32 " + std::string(crc) + ", the render printed " +
                             d.figures.at("crc32"));
  return d;
}

}  // namespace htx
