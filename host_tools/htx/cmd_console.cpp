// htx console and htx grab: talk to the console firmware (docs/console.md) on a board's serial port
// or on the pseudo-terminal of `htx sim --uart pty`.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "htx/console/console_client.hpp"
#include "htx/console/serial_port.hpp"
#include "console_payload.hpp"
#include "line_input.hpp"
#include "line_reader.hpp"
#include "htx/model/image_io.hpp"
#include "output_path.hpp"

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
  cmd->add_option("--timeout", a->timeout_s, "longest silence to wait through, seconds")
      ->check(timeout_seconds())
      ->capture_default_str();
}

std::chrono::milliseconds timeout_of(const PortArgs& a) { return timeout_ms(a.timeout_s); }

// Runs a step on local files (loading a scene or an image, writing a PNG), its failure reported as
// std::invalid_argument: in typed mode that is the line's error and the session goes on, while an
// error of the line to the console (std::runtime_error) ends it.
template <class Step>
auto local_file_step(Step step) -> decltype(step()) {
  try {
    return step();
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
}

// Downloads the frame into a PNG, showing progress on stderr (the callers check `out`'s directory
// first, before the port is opened or the frame asked for).
void grab_to_png(console::ConsoleClient& client, const std::string& out) {
  size_t shown = 0;
  const console::GrabbedFrame f = client.grab([&shown](size_t bytes) {
    if (bytes >= shown + 4096) {
      shown = bytes;
      std::cerr << "\rgrab: " << bytes << " bytes" << std::flush;
    }
  });
  if (shown) std::cerr << "\n";
  local_file_step([&] { write_png(out, image_from_rgb565(f.width, f.height, f.pixels)); });
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x", f.crc32);
  std::cout << "grab: " << f.width << "x" << f.height << " frame, " << f.coded_bytes << " bytes in "
            << f.data_packets << " packets, crc32 " << crc << " -> " << out << "\n";
}

void upload(console::ConsoleClient& client, const std::vector<uint8_t>& packed,
            console::ConsoleClient::Payload payload = console::ConsoleClient::Payload::kScene, unsigned slot = 0) {
  const size_t resent = client.resent_packets();
  const std::string verdict = client.upload(
      packed,
      [&packed](size_t sent) { std::cerr << "\rupload: " << sent << " of " << packed.size() << " bytes" << std::flush; },
      payload, slot);
  std::cerr << "\n";
  if (client.resent_packets() > resent)
    std::cerr << "upload: " << client.resent_packets() - resent << " packets sent again (the console missed them)\n";
  std::cout << verdict;
}

// The scene, then its textures, each into its slot (only once the scene was taken: a refused
// scene changes nothing).
void upload_scene(console::ConsoleClient& client, const ScenePayload& p) {
  if (!p.note.empty()) std::cerr << "upload: " << p.note << "\n";
  upload(client, p.scene);
  for (size_t slot = 0; slot < p.textures.size(); ++slot) {
    if (p.textures[slot].empty()) continue;
    try {
      upload(client, p.textures[slot], console::ConsoleClient::Payload::kTexture, static_cast<unsigned>(slot));
    } catch (const std::invalid_argument& e) {
      // The scene stays taken: say so, rather than let "unchanged" read as the whole upload's.
      throw std::invalid_argument("the scene was taken, but not its texture for slot " + std::to_string(slot) + ": " +
                                  e.what());
    }
  }
}

// While it lives, SIGINT (Ctrl-C) asks the running command to stop (asked()) instead of ending
// htx; a second one before the first was taken ends htx as Ctrl-C would have. Outside it (at the
// prompt, where libedit reads) Ctrl-C keeps its usual meaning.
class InterruptStops {
 public:
  InterruptStops() {
    pending_ = 0;
    struct sigaction on {};
    on.sa_handler = &InterruptStops::on_interrupt;
    sigemptyset(&on.sa_mask);
    sigaction(SIGINT, &on, &before_);
  }
  ~InterruptStops() { sigaction(SIGINT, &before_, nullptr); }
  InterruptStops(const InterruptStops&) = delete;
  InterruptStops& operator=(const InterruptStops&) = delete;
  // Whether Ctrl-C was pressed since the last call.
  static bool asked() { return pending_.exchange(0) != 0; }

 private:
  static void on_interrupt(int) {
    if (pending_.exchange(1) != 0) {  // the first not yet taken: quit
      signal(SIGINT, SIG_DFL);
      raise(SIGINT);
    }
  }
  static inline std::atomic<int> pending_{0};
  struct sigaction before_ {};
};

struct ConsoleArgs : PortArgs {
  std::vector<std::string> commands;
};

// One line typed or given with -c. `grab FILE.png`, `upload SCENE` and `texture FILE.png` are
// carried out by htx (their exchanges are binary), and `baud N` switches the port with the
// console; everything else goes to the console as it is, its output shown as it comes, and
// `stop` (typed mode: a line typed meanwhile) may stop it (ConsoleClient::converse).
// Returns false after quit. With `refused`, sets it when the console answers with an error line
// (or refuses a `baud`).
bool run_line(console::SerialPort& port, console::ConsoleClient& client, const std::string& line,
              const std::function<bool()>& stop = {}, bool* refused = nullptr) {
  std::istringstream words(line);
  std::string verb, arg, format, extra, more;
  words >> verb >> arg >> format >> extra >> more;
  if (verb == "quit" && arg.empty()) {  // (`quit` with more words is the console's error)
    port.write("quit\r");
    return false;
  }
  if (verb == "baud") {
    // The console switches after its `ok`; the port must follow it there.
    if (arg.empty() || !format.empty() || arg.find_first_not_of("0123456789") != std::string::npos || arg.size() > 9)
      throw std::invalid_argument("usage: baud N");
    try {
      client.set_baud(static_cast<unsigned>(std::stoul(arg)));
      std::cout << "baud " << arg << "\n" << std::flush;
    } catch (const std::invalid_argument& e) {
      // A rate this port cannot take (refused before the console was asked) or the console's
      // refusal: either way the line is as it was.
      std::cout << e.what() << "\n" << std::flush;
      if (refused) *refused = true;
    }
    return true;
  }
  if (verb == "grab" || verb == "upload" || verb == "texture") {
    // Only `texture` takes more words: the format, then the slot.
    const bool is_slot = extra.empty() || extra.find_first_not_of("0123456789") == std::string::npos;
    if (arg.empty() || !more.empty() || !is_slot || extra.size() > 3 || (verb != "texture" && !format.empty()))
      throw std::invalid_argument(verb == "grab"     ? "usage: grab FRAME.png"
                                  : verb == "upload" ? "usage: upload SCENE (built-in or FILE.obj)"
                                                     : "usage: texture IMAGE.png [rgb565|rgba4444 [SLOT]]");
    if (verb == "grab") {
      local_file_step([&] { require_output_dir(arg); });
      grab_to_png(client, arg);
    } else if (verb == "upload") {
      upload_scene(client, local_file_step([&] { return scene_payload(arg, "160x120", true); }));
    } else {
      upload(client, local_file_step([&] { return packed_texture(arg, format.empty() ? "rgb565" : format); }),
             console::ConsoleClient::Payload::kTexture, extra.empty() ? 0u : static_cast<unsigned>(std::stoul(extra)));
    }
    return true;
  }
  // A line the console would read to its end only to refuse (a long one at the line's rate: a
  // 20 KB line took 12 s, an 8 MB one most of an hour) is refused here, in the console's words.
  if (line.size() > console_app::kMaxLine) {
    std::cout << "error: line longer than " << console_app::kMaxLine << " characters (not sent)\n" << std::flush;
    if (refused) *refused = true;
    return true;
  }
  // The answer's lines that start with "error:" are the console's refusals.
  std::string line_start;  // the current answer line's first characters, up to the marker's length
  static constexpr std::string_view kError = "error:";
  client.converse(
      line,
      [&](const std::string& text) {
        std::cout << text << std::flush;
        for (const char c : text) {
          if (c == '\n') {
            line_start.clear();
          } else if (line_start.size() < kError.size()) {
            line_start += c;
            if (refused && line_start == kError) *refused = true;
          }
        }
      },
      stop);
  if (verb == "help" && arg.empty())  // what htx itself does with a line (the console's `upload` is its protocol)
    std::cout << "htx console also takes:\n"
                 "  upload SCENE          send a built-in scene or FILE.obj with its textures (then `render upload`)\n"
                 "  texture IMAGE [rgb565|rgba4444 [SLOT]]  send an image as a texture into a slot\n"
                 "  grab FILE.png         download the frame drawn last\n"
                 "  baud N                switch the console and this port together\n"
                 "  (a line typed while the console works stops a spin and runs after it)\n"
              << std::flush;
  return true;
}

void run_console(const ConsoleArgs& a) {
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  if (!a.commands.empty()) {
    // Every command runs, as typed ones would; a script learns of refusals from the status.
    size_t refusals = 0;
    std::string first_refused;
    bool quit = false;
    for (const std::string& c : a.commands) {
      std::cout << console::kPrompt << c << "\n" << std::flush;
      bool refused = false;
      quit = !run_line(port, client, c, {}, &refused);
      if (refused && refusals++ == 0) first_refused = c;
      if (quit) break;
    }
    if (refusals > 0)
      throw std::runtime_error("the console answered " + std::to_string(refusals) + " of the commands with an error "
                               "(the first: `" + first_refused + "`)");
    return;
  }
  // Interactive: a line from stdin at a time (LineInput: edited, with history, on a terminal),
  // each answered before the next is sent (the console's receive FIFO is 16 bytes: typing ahead of
  // it would lose characters). A line typed while the console works waits its turn, and stops a
  // `spin` (a single key goes to the console: see ConsoleClient::converse); it then runs, shown
  // after the prompt. A mistyped grab or upload is reported and the session goes on.
  // Ctrl-C while the console works stops it as a typed line does (a `spin` ends after its frame),
  // rather than leaving it spinning with no client; a second Ctrl-C before it has stopped quits.
  LineInput input;
  std::string line;
  while (input.read(console::kPrompt, &line)) {
    try {
      const InterruptStops interrupts;
      if (!run_line(port, client, line, [&input] { return input.line_typed() || InterruptStops::asked(); })) break;
    } catch (const std::invalid_argument& e) {
      std::cout << "error: " << e.what() << "\n";
    }
  }
}

struct GrabArgs : PortArgs {
  std::string out;
};

void run_grab(const GrabArgs& a) {
  require_given_path(a.out, "--out");
  require_output_dir(a.out);
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
  unsigned slot = 0;
  bool no_texture = false;
  uint32_t mesh_vertices = render::kMaxPackedMeshVertices;
};

void run_upload(const UploadArgs& a) {
  if (a.scene.empty() && a.texture.empty()) throw std::invalid_argument("upload: give a SCENE, --texture FILE, or both");
  // Bad scenes and images fail before the port opens.
  ScenePayload scene;
  if (!a.scene.empty()) scene = scene_payload(a.scene, a.size, a.texture.empty() && !a.no_texture, a.mesh_vertices);
  if (!a.texture.empty()) {
    scene.textures.assign(a.slot + 1, {});
    scene.textures[a.slot] = packed_texture(a.texture, a.format);
  }
  console::SerialPort port(a.port, a.baud);
  console::ConsoleClient client(port, timeout_of(a));
  client.sync();
  if (!scene.scene.empty()) upload_scene(client, scene);
  else upload(client, scene.textures[a.slot], console::ConsoleClient::Payload::kTexture, a.slot);
}

}  // namespace

void register_console(CLI::App& app) {
  auto args = std::make_shared<ConsoleArgs>();
  auto* cmd = app.add_subcommand("console", "Talk to the console firmware: run commands, or type them");
  add_port_options(cmd, args.get());
  cmd->add_option("-c,--command", args->commands,
                  "run this command and print its output (repeatable; `grab FILE.png`, `upload SCENE`, "
                  "`texture FILE.png [rgb565|rgba4444 [SLOT]]` and `baud N` are carried out by htx); without any, read "
                  "commands from stdin");
  cmd->callback([args] { run_console(*args); });

  auto gargs = std::make_shared<GrabArgs>();
  auto* grab = app.add_subcommand("grab", "Download the console firmware's current frame as a PNG");
  add_port_options(grab, gargs.get());
  grab->add_option("--out", gargs->out, "output PNG")->required();
  grab->callback([gargs] { run_grab(*gargs); });

  auto uargs = std::make_shared<UploadArgs>();
  auto* up = app.add_subcommand(
      "upload",
      "Send a scene (built-in NAME[:k=v,...] or FILE.obj, with its textures) and/or a texture (an image) to the console "
      "firmware");
  add_port_options(up, uargs.get());
  up->add_option("scene", uargs->scene, "built-in scene spec or an OBJ file");
  up->add_option("--size", uargs->size, "the console's screen, for the camera's aspect")->capture_default_str();
  up->add_option("--texture", uargs->texture,
                 "an image (PNG, ...) whose sides are powers of two in 8..256, at most 1,024 texels, sent instead "
                 "of the scene's textures into texture slot --slot: the compiled-in scenes draw with slot 0, an "
                 "uploaded scene's meshes each with their own slot");
  up->add_option("--slot", uargs->slot, "the texture slot --texture goes into")
      ->check(CLI::Range(0u, render::kConsoleTextureSlots - 1))
      ->needs(up->get_option("--texture"))
      ->capture_default_str();
  up->add_option("--format", uargs->format, "the texture's texel format: rgb565 or rgba4444")
      ->check(CLI::IsMember({"rgb565", "rgba4444"}))
      ->needs(up->get_option("--texture"))
      ->capture_default_str();
  up->add_option("--mesh-vertices", uargs->mesh_vertices,
                 "split meshes into parts of at most this many vertices (the console's vertex cache)")
      ->check(CLI::Range(4u, render::kMaxPackedMeshVertices))
      ->capture_default_str();
  up->add_flag("--no-texture", uargs->no_texture,
               "send the scene without its textures (the console keeps the ones it has)")
      ->excludes(up->get_option("--texture"));
  up->callback([uargs, up] {
    // The scene's own options mean nothing for a texture alone.
    if (uargs->scene.empty())
      for (const char* option : {"--size", "--mesh-vertices", "--no-texture"})
        if (up->count(option) > 0) throw std::invalid_argument(std::string(option) + " is for a SCENE upload");
    run_upload(*uargs);
  });
}

}  // namespace htx
