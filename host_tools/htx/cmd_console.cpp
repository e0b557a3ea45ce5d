// htx console and htx grab: talk to the console firmware (docs/console.md) on a board's serial port
// or on the pseudo-terminal of `htx sim --uart pty`.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "htx/console/console_client.hpp"
#include "htx/console/serial_port.hpp"
#include "frame_size.hpp"
#include "htx/host/render_scene.hpp"
#include "htx/model/image_io.hpp"
#include "htx/model/scenes.hpp"
#include "htx/fw/texel.h"
#include "htx/render/scene_pack.h"
#include "htx/render/texture_pack.h"

namespace htx {

namespace {

struct PortArgs {
  std::string port;
  unsigned baud = 115200;
  double timeout_s = 120;
};

void add_port_options(CLI::App* cmd, PortArgs* a) {
  cmd->add_option("--port", a->port, "serial device, or the pty that `htx sim --uart pty` printed")->required();
  cmd->add_option("--baud", a->baud, "baud rate (a pty ignores it)")->capture_default_str();
  cmd->add_option("--timeout", a->timeout_s, "longest silence to wait through, seconds")->capture_default_str();
}

std::chrono::milliseconds timeout_of(const PortArgs& a) {
  if (!(a.timeout_s > 0)) throw std::invalid_argument("--timeout must be > 0 seconds");
  return std::chrono::milliseconds(static_cast<long long>(a.timeout_s * 1000));
}

// The packed form of a scene as the console takes it (htx/render/scene_pack.h).
std::vector<uint8_t> packed_scene(const std::string& spec, const std::string& size) {
  int width = 0, height = 0;
  parse_size(size, width, height);
  // The firmware's form of the scene (as the render firmware's compiled-in scenes are made), packed.
  const host::RenderScene rs = host::to_render_scene(load_scene(spec), width, height);
  std::vector<render::Mesh> meshes;
  for (const host::RenderScene::MeshData& d : rs.meshes) meshes.push_back(d.mesh);
  const uint32_t count = static_cast<uint32_t>(meshes.size());
  std::vector<uint8_t> packed(render::packed_scene_size(meshes.data(), count));
  if (render::pack_scene(rs.view_proj, rs.cull_backfaces, meshes.data(), count, packed.data(), packed.size()) == 0)
    throw std::runtime_error("'" + spec + "' does not fit the packed scene format (65535 vertices or triangles a mesh)");
  return packed;
}

// The packed form of an image as the console takes it as its texture (htx/render/texture_pack.h):
// sides powers of two in 8..256, each pixel encoded in `format`, the image's bottom row as texel
// row 0 (v = 0), as the model reads an OBJ's texture.
std::vector<uint8_t> packed_texture(const std::string& path, const std::string& format_name) {
  uint8_t format = 0;
  if (format_name == "rgb565") format = fw::kTexelRgb565;
  else if (format_name == "rgba4444") format = fw::kTexelRgba4444;
  else throw std::invalid_argument("--format must be rgb565 or rgba4444, not '" + format_name + "'");
  const Image img = load_image(path);
  const auto log2_of = [](int n) {
    int l = 0;
    while ((1 << l) < n) ++l;
    return (1 << l) == n ? l : -1;
  };
  const int lw = log2_of(img.width), lh = log2_of(img.height);
  if (lw < 3 || lw > 8 || lh < 3 || lh > 8)
    throw std::invalid_argument("texture '" + path + "' is " + std::to_string(img.width) + "x" +
                                std::to_string(img.height) + "; sides must be powers of two in 8..256");
  std::vector<uint16_t> texels(img.rgba.size() / 4);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const uint8_t* p = &img.rgba[4 * (static_cast<size_t>(img.height - 1 - y) * img.width + x)];
      const uint32_t rgba8 = p[0] | (p[1] << 8) | (p[2] << 16) | (uint32_t{p[3]} << 24);
      texels[static_cast<size_t>(y) * img.width + x] = static_cast<uint16_t>(fw::encode_texel(format, rgba8));
    }
  std::vector<uint8_t> packed(render::packed_texture_size(lw, lh));
  if (render::pack_texture(static_cast<uint8_t>(lw), static_cast<uint8_t>(lh), format, texels.data(), packed.data(),
                           packed.size()) != packed.size())
    throw std::logic_error("pack_texture refused a checked texture");
  return packed;
}

// Downloads the frame into a PNG, showing progress on stderr.
void grab_to_png(console::ConsoleClient& client, const std::string& out) {
  size_t shown = 0;
  const console::GrabbedFrame f = client.grab([&shown](size_t bytes) {
    if (bytes >= shown + 4096) {
      shown = bytes;
      std::cerr << "\rgrab: " << bytes << " bytes" << std::flush;
    }
  });
  if (shown) std::cerr << "\n";
  write_png(out, image_from_rgb565(f.width, f.height, f.pixels));
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x", f.crc32);
  std::cout << "grab: " << f.width << "x" << f.height << " frame, " << f.coded_bytes << " bytes in "
            << f.data_packets << " packets, crc32 " << crc << " -> " << out << "\n";
}

void upload(console::ConsoleClient& client, const std::vector<uint8_t>& packed,
            console::ConsoleClient::Payload payload = console::ConsoleClient::Payload::kScene) {
  const std::string verdict = client.upload(
      packed,
      [&packed](size_t sent) { std::cerr << "\rupload: " << sent << " of " << packed.size() << " bytes" << std::flush; },
      payload);
  std::cerr << "\n";
  std::cout << verdict;
}

struct ConsoleArgs : PortArgs {
  std::vector<std::string> commands;
};

// One line typed or given with -c. `grab FILE.png`, `upload SCENE` and `texture FILE.png` are
// carried out by htx (their exchanges are binary); everything else goes to the console as it is.
// Returns false after quit.
bool run_line(console::SerialPort& port, console::ConsoleClient& client, const std::string& line) {
  if (line == "quit") {
    port.write("quit\r");
    return false;
  }
  std::istringstream words(line);
  std::string verb, arg, extra;
  words >> verb >> arg >> extra;
  if (verb == "grab" || verb == "upload" || verb == "texture") {
    if (arg.empty() || !extra.empty())
      throw std::invalid_argument(verb == "grab"     ? "usage: grab FRAME.png"
                                  : verb == "upload" ? "usage: upload SCENE (built-in or FILE.obj)"
                                                     : "usage: texture IMAGE.png (RGB565)");
    if (verb == "grab") grab_to_png(client, arg);
    else if (verb == "upload") upload(client, packed_scene(arg, "160x120"));
    else upload(client, packed_texture(arg, "rgb565"), console::ConsoleClient::Payload::kTexture);
    return true;
  }
  std::cout << client.command(line) << std::flush;
  return true;
}

void run_console(const ConsoleArgs& a) {
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  if (!a.commands.empty()) {
    for (const std::string& c : a.commands) {
      std::cout << console::kPrompt << c << "\n" << std::flush;
      if (!run_line(port, client, c)) return;
    }
    return;
  }
  // Interactive: a line from stdin at a time, each answered before the next is sent (the console's
  // receive FIFO is 16 bytes: typing ahead of it would lose characters). A mistyped grab or upload
  // is reported and the session goes on.
  std::string line;
  for (;;) {
    std::cout << console::kPrompt << std::flush;
    if (!std::getline(std::cin, line)) break;
    try {
      if (!run_line(port, client, line)) break;
    } catch (const std::invalid_argument& e) {
      std::cout << "error: " << e.what() << "\n";
    }
  }
}

struct GrabArgs : PortArgs {
  std::string out;
};

void run_grab(const GrabArgs& a) {
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  grab_to_png(client, a.out);
}

struct UploadArgs : PortArgs {
  std::string scene;
  std::string size = "160x120";
  std::string texture;
  std::string format = "rgb565";
};

void run_upload(const UploadArgs& a) {
  if (a.scene.empty() && a.texture.empty()) throw std::invalid_argument("upload: give a SCENE, --texture FILE, or both");
  // Bad scenes and images fail before the port opens.
  const std::vector<uint8_t> scene = a.scene.empty() ? std::vector<uint8_t>{} : packed_scene(a.scene, a.size);
  const std::vector<uint8_t> texture = a.texture.empty() ? std::vector<uint8_t>{} : packed_texture(a.texture, a.format);
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  if (!scene.empty()) upload(client, scene);
  if (!texture.empty()) upload(client, texture, console::ConsoleClient::Payload::kTexture);
}

}  // namespace

void register_console(CLI::App& app) {
  auto args = std::make_shared<ConsoleArgs>();
  auto* cmd = app.add_subcommand("console", "Talk to the console firmware: run commands, or type them");
  add_port_options(cmd, args.get());
  cmd->add_option("-c,--command", args->commands,
                  "run this command and print its output (repeatable; `grab FILE.png`, `upload SCENE` and "
                  "`texture FILE.png` are carried out by htx); without any, read commands from stdin");
  cmd->callback([args] { run_console(*args); });

  auto gargs = std::make_shared<GrabArgs>();
  auto* grab = app.add_subcommand("grab", "Download the console firmware's current frame as a PNG");
  add_port_options(grab, gargs.get());
  grab->add_option("--out", gargs->out, "output PNG")->required();
  grab->callback([gargs] { run_grab(*gargs); });

  auto uargs = std::make_shared<UploadArgs>();
  auto* up = app.add_subcommand(
      "upload", "Send a scene (built-in NAME[:k=v,...] or FILE.obj) and/or a texture (an image) to the console firmware");
  add_port_options(up, uargs.get());
  up->add_option("scene", uargs->scene, "built-in scene spec or an OBJ file");
  up->add_option("--size", uargs->size, "the console's screen, for the camera's aspect")->capture_default_str();
  up->add_option("--texture", uargs->texture,
                 "an image (PNG, ...) whose sides are powers of two in 8..256, at most 1,024 texels: every render "
                 "then draws with it");
  up->add_option("--format", uargs->format, "the texture's texel format: rgb565 or rgba4444")->capture_default_str();
  up->callback([uargs] { run_upload(*uargs); });
}

}  // namespace htx
