// htx console and htx grab: talk to the console firmware (docs/console.md) on a board's serial port
// or on the pseudo-terminal of `htx sim --uart pty`.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
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
#include "htx/render/scene_pack.h"

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

struct ConsoleArgs : PortArgs {
  std::vector<std::string> commands;
};

void run_console(const ConsoleArgs& a) {
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  if (!a.commands.empty()) {
    for (const std::string& c : a.commands) {
      std::cout << console::kPrompt << c << "\n" << std::flush;
      if (c == "quit") {
        port.write("quit\r");
        return;
      }
      if (c == "grab") throw std::invalid_argument("use `htx grab --port " + a.port + " --out FRAME.png` for grab");
      if (c.rfind("upload", 0) == 0)
        throw std::invalid_argument("use `htx upload SCENE --port " + a.port + "` to send a scene");
      std::cout << client.command(c) << std::flush;
    }
    return;
  }
  // Interactive: a line from stdin at a time, each answered before the next is sent (the console's
  // receive FIFO is 16 bytes: typing ahead of it would lose characters).
  std::string line;
  for (;;) {
    std::cout << console::kPrompt << std::flush;
    if (!std::getline(std::cin, line)) break;
    if (line == "quit") {
      port.write("quit\r");
      break;
    }
    if (line == "grab" || line.rfind("upload", 0) == 0) {
      std::cout << "use `htx grab --port " << a.port << " --out FRAME.png` to download the frame, `htx upload SCENE --port "
                << a.port << "` to send a scene\n";
      continue;
    }
    std::cout << client.command(line) << std::flush;
  }
}

struct GrabArgs : PortArgs {
  std::string out;
};

void run_grab(const GrabArgs& a) {
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  size_t shown = 0;
  const console::GrabbedFrame f = client.grab([&shown](size_t bytes) {
    if (bytes >= shown + 4096) {
      shown = bytes;
      std::cerr << "\rgrab: " << bytes << " bytes" << std::flush;
    }
  });
  if (shown) std::cerr << "\n";
  write_png(a.out, image_from_rgb565(f.width, f.height, f.pixels));
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x", f.crc32);
  std::cout << "grab: " << f.width << "x" << f.height << " frame, " << f.coded_bytes << " bytes in "
            << f.data_packets << " packets, crc32 " << crc << " -> " << a.out << "\n";
}

struct UploadArgs : PortArgs {
  std::string scene;
  std::string size = "160x120";
};

void run_upload(const UploadArgs& a) {
  int width = 0, height = 0;
  parse_size(a.size, width, height);
  // The firmware's form of the scene (as the render firmware's compiled-in scenes are made), packed.
  const host::RenderScene rs = host::to_render_scene(load_scene(a.scene), width, height);
  std::vector<render::Mesh> meshes;
  for (const host::RenderScene::MeshData& d : rs.meshes) meshes.push_back(d.mesh);
  const uint32_t count = static_cast<uint32_t>(meshes.size());
  std::vector<uint8_t> packed(render::packed_scene_size(meshes.data(), count));
  if (render::pack_scene(rs.view_proj, rs.cull_backfaces, meshes.data(), count, packed.data(), packed.size()) == 0)
    throw std::runtime_error("'" + a.scene + "' does not fit the packed scene format (65535 vertices or triangles a mesh)");
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  const std::string verdict = client.upload(packed, [&packed](size_t sent) {
    std::cerr << "\rupload: " << sent << " of " << packed.size() << " bytes" << std::flush;
  });
  std::cerr << "\n";
  std::cout << verdict;
}

}  // namespace

void register_console(CLI::App& app) {
  auto args = std::make_shared<ConsoleArgs>();
  auto* cmd = app.add_subcommand("console", "Talk to the console firmware: run commands, or type them");
  add_port_options(cmd, args.get());
  cmd->add_option("-c,--command", args->commands, "run this command and print its output (repeatable); "
                                                  "without any, read commands from stdin");
  cmd->callback([args] { run_console(*args); });

  auto gargs = std::make_shared<GrabArgs>();
  auto* grab = app.add_subcommand("grab", "Download the console firmware's current frame as a PNG");
  add_port_options(grab, gargs.get());
  grab->add_option("--out", gargs->out, "output PNG")->required();
  grab->callback([gargs] { run_grab(*gargs); });

  auto uargs = std::make_shared<UploadArgs>();
  auto* upload = app.add_subcommand("upload", "Send a scene (built-in NAME[:k=v,...] or FILE.obj) to the console firmware");
  add_port_options(upload, uargs.get());
  upload->add_option("scene", uargs->scene, "built-in scene spec or an OBJ file")->required();
  upload->add_option("--size", uargs->size, "the console's screen, for the camera's aspect")->capture_default_str();
  upload->callback([uargs] { run_upload(*uargs); });
}

}  // namespace htx
