#include "console_render.hpp"

#include <cstdio>
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

}  // namespace

ConsoleDrawn draw_on_console(console::ConsoleClient& client, const ConsoleDraw& draw) {
  const ScenePayload& payload = draw.payload;
  const auto step = [&draw](const std::string& what) {
    if (draw.on_step) draw.on_step(what);
  };
  ConsoleDrawn d;
  if (!payload.note.empty()) step(payload.note);
  // The scene first: a refused scene leaves the console's textures as they were too.
  step("upload: scene of " + std::to_string(payload.scene.size()) + " bytes");
  client.upload(payload.scene);
  for (size_t slot = 0; slot < payload.textures.size(); ++slot) {
    if (payload.textures[slot].empty()) continue;
    step("upload: texture " + std::to_string(slot) + " of " + std::to_string(payload.textures[slot].size()) +
         " bytes");
    client.upload(payload.textures[slot], {}, console::ConsoleClient::Payload::kTexture, static_cast<unsigned>(slot));
  }
  step("set method " + draw.method + ", tolerance " + draw.tolerance + ", filter " + draw.filter + "; render");
  set(client, "method", draw.method);
  set(client, "tolerance", draw.tolerance);
  set(client, "filter", draw.filter);
  d.figures = render_figures(client.command("render upload"));
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
