#include "commands.hpp"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "frame_crc.hpp"
#include "frame_download.hpp"
#include "frame_pages.hpp"
#include "line_reader.hpp"
#include "scene_store.hpp"
#include "scene_turn.hpp"
#include "scene_upload.hpp"
#include "texture_store.hpp"
#include "htx/hal/framebuffer.h"
#include "htx/hal/raster.h"
#include "htx/hal/texture.h"
#include "htx/hal/timer.h"
#include "htx/hal/uart.h"
#include "htx/hal/video.h"
#include "htx/render/fixed.h"
#include "htx/render/tri_state.h"
#include "htx_regs.h"
#include "scene_render.hpp"
#include "scenes.hpp"
#include "soc_config.hpp"

namespace console_app {

namespace {

constexpr const char* kVersion = "0.1";
// Status reads to wait for the video's last flip: a frame is 420,000 clocks, a read takes a few.
constexpr uint32_t kFlipPolls = 1'000'000;
constexpr uint32_t kSpinDefaultFrames = 60, kSpinMaxFrames = 3600;
// Status reads to wait for the line to drain: the longest answer is a few hundred bytes.
constexpr uint32_t kFlushPolls = 10'000'000;

// The methods' and filters' names (htx/render/tri_state.h); `set filter scene` keeps each mesh's own.
using htx::render::kFilterNames;
using htx::render::kMethodNames;
constexpr uint32_t kMethodCount = htx::render::kMethodNameCount;
constexpr uint32_t kFilterCount = htx::render::kFilterNameCount;

const char* filter_text(uint8_t filter) { return filter < kFilterCount ? kFilterNames[filter] : "scene"; }

struct Settings {
  render_app::DrawSettings draw;
  uint32_t tolerance_denominator = 16;  // AUTO's tolerance: 1 / this texel (1..65536)
  char method_text[12] = "auto";
};

Settings g_settings;
render_app::DrawResult g_last;
const char* g_last_scene = nullptr;

// Splits off the next space-separated word (NUL-terminating it); returns nullptr at the end.
char* next_word(char** rest) {
  char* s = *rest;
  while (*s == ' ') ++s;
  if (*s == '\0') return nullptr;
  char* w = s;
  while (*s != '\0' && *s != ' ') ++s;
  if (*s == ' ') *s++ = '\0';
  *rest = s;
  return w;
}

// A decimal number in [lo, hi] and nothing else.
bool parse_uint(const char* s, uint32_t lo, uint32_t hi, uint32_t* out) {
  if (*s == '\0') return false;
  uint32_t v = 0;
  for (; *s; ++s) {
    if (*s < '0' || *s > '9') return false;
    const uint32_t d = static_cast<uint32_t>(*s - '0');
    if (v > (hi - d) / 10) return false;  // v * 10 + d > hi, checked before it could wrap
    v = v * 10 + d;
  }
  if (v < lo) return false;
  *out = v;
  return true;
}

void error(const char* what, const char* arg = "") { printf("error: %s%s\r\n", what, arg); }

void cmd_help() {
  fputs("commands:\r\n"
        "  help                  this list\r\n"
        "  info                  the SoC, the screen and the settings\r\n"
        "  scenes                the scenes `render` draws\r\n"
        "  set method NAME       auto, affine, subdivN (N = 2..64), recip_lut, recip_nr, divfree\r\n"
        "  set tolerance 1/N     AUTO's largest predicted texel error (N = 1..65536)\r\n"
        "  set filter NAME       nearest, bilinear, trilinear, or scene (each mesh's own)\r\n"
        "  render SCENE [over] [hold]  draw a scene (over the last frame; not shown yet); its figures\r\n"
        "  spin SCENE [FRAMES] [crc]  FRAMES renders (60) turning once about its middle; a key stops\r\n"
        "  upload SIZE CRC32     receive a packed scene as packets (for `htx upload`); SCENE `upload`\r\n"
        "  texture SIZE CRC32 [SLOT]  receive a packed texture into a slot (for `htx upload`)\r\n"
        "  stats                 the raster unit's counters after the last render\r\n"
        "  video on|off          show the framebuffer on the board's screen (640x480, 60 Hz), or black\r\n"
        "  baud N                switch the serial line to N baud (after `ok`; the host must follow)\r\n"
        "  grab                  send the frame as binary packets (for `htx grab`)\r\n"
        "  quit                  leave the console (the simulation ends)\r\n",
        stdout);
}

void cmd_info() {
  const uint32_t hz = HTX_SYSCTRL->CLOCK_HZ;
  printf("hypertex console %s: soc %08lx at %lu Hz, serial %lu baud\r\n", kVersion,
         static_cast<unsigned long>(HTX_SYSCTRL->ID), static_cast<unsigned long>(hz),
         static_cast<unsigned long>(hz / htx::hal::uart_divisor()));
  printf("screen %ldx%ld rgb565; methods", static_cast<long>(render_app::kWidth),
         static_cast<long>(render_app::kHeight));
  // What this GPU builds (CAPS), in `set`'s names.
  const uint32_t methods = htx::hal::raster_caps().methods;
  for (uint32_t m = 0; m < kMethodCount; ++m)
    if ((methods >> m) & 1u) printf(" %s", kMethodNames[m]);
  fputs("; filters", stdout);
  const uint32_t filters = htx::hal::texture_caps().filters;
  for (uint32_t f = 0; f < kFilterCount; ++f)
    if ((filters >> f) & 1u) printf(" %s", kFilterNames[f]);
  fputs("\r\n", stdout);
  printf("method %s; tolerance 1/%lu texel; filter %s\r\n", g_settings.method_text,
         static_cast<unsigned long>(g_settings.tolerance_denominator), filter_text(g_settings.draw.filter));
  const uint32_t slots = texture_slot_count();
  for (uint32_t slot = 0; slot < slots; ++slot) {
    const TextureInfo t = texture_in_slot(slot);
    if (t.present())
      printf("texture %lu: %ux%u %s (%s)\r\n", static_cast<unsigned long>(slot), 1u << t.log2_width,
             1u << t.log2_height, texture_format_name(t.format), t.uploaded ? "uploaded" : "checkerboard");
    else
      printf("texture %lu: none (its meshes draw with texture 0)\r\n", static_cast<unsigned long>(slot));
  }
  printf("texture memory: %lu of %lu blocks (2x2 texels) in use\r\n",
         static_cast<unsigned long>(texture_blocks_in_use()), static_cast<unsigned long>(texture_memory_blocks()));
  const htx::hal::VideoMode m = htx::hal::video_mode();
  printf("video 640x480 60 Hz showing %lux%lu x%lu: %s, frame %lu, page %lu of %lu%s\r\n",
         static_cast<unsigned long>(m.src_width), static_cast<unsigned long>(m.src_height),
         static_cast<unsigned long>(m.scale), htx::hal::video_enabled() ? "on" : "off",
         static_cast<unsigned long>(htx::hal::video_frames()), static_cast<unsigned long>(shown_frame_page()),
         static_cast<unsigned long>(frame_pages()), htx::hal::video_underrun() ? " (a line came late since video on)" : "");
}

void cmd_video(char* rest) {
  const char* what = next_word(&rest);
  if (!what || next_word(&rest) || (strcmp(what, "on") != 0 && strcmp(what, "off") != 0))
    return error("usage: video on|off");
  htx::hal::video_enable(strcmp(what, "on") == 0);
  htx::hal::video_clear_underrun();
  printf("video %s\r\n", what);
}

// The fewest clocks a bit the console takes: its packet receive loop (an upload) must read each
// byte before the 16-byte receive FIFO fills. Measured on the simulated SoC (docs/console.md):
// at 4 clocks a bit (3 Mbaud at 12 MHz) every packet overflowed it, at 6 (2 Mbaud) the 62 KB of
// `tunnel` went without one packet sent again.
constexpr uint32_t kMinClocksPerBit = 6;

// `baud N`: the UART's divisor for N at the SoC's clock, when it is one (4..65535 clocks a bit,
// within 2 % of N: two ends 2 % apart drift a fifth of a bit over a frame) and not faster than
// kMinClocksPerBit. `ok` goes out at the old rate; then the line drains, a pause of 20 ms gives
// the host time to switch its port, and the prompt comes at the new rate.
void cmd_baud(char* rest) {
  const char* text = next_word(&rest);
  uint32_t baud = 0;
  if (!text || next_word(&rest) || !parse_uint(text, 1, 100'000'000, &baud)) return error("usage: baud N");
  const uint32_t hz = HTX_SYSCTRL->CLOCK_HZ;
  const uint32_t divisor = (hz + baud / 2) / baud;
  const uint32_t actual = divisor ? hz / divisor : 0;
  const uint32_t off = actual > baud ? actual - baud : baud - actual;
  if (divisor < 4 || divisor > 0xFFFF || uint64_t{off} * 50 > baud) {
    printf("error: %lu baud is not one this UART makes at %lu Hz (4..65535 clocks a bit, within 2 %%)\r\n",
           static_cast<unsigned long>(baud), static_cast<unsigned long>(hz));
    return;
  }
  if (divisor < kMinClocksPerBit) {
    printf("error: %lu baud is faster than the console reads an upload (%lu clocks a bit or more: up to %lu baud "
           "at %lu Hz)\r\n",
           static_cast<unsigned long>(baud), static_cast<unsigned long>(kMinClocksPerBit),
           static_cast<unsigned long>(hz / kMinClocksPerBit), static_cast<unsigned long>(hz));
    return;
  }
  printf("ok %lu baud\r\n", static_cast<unsigned long>(actual));
  htx::hal::uart_flush(kFlushPolls);
  const uint64_t until = htx::hal::cpu_cycles() + hz / 50;
  while (htx::hal::cpu_cycles() < until) {
  }
  htx::hal::uart_set_divisor(divisor);
}

void cmd_scenes() {
  uint32_t n = 0;
  const render_app::SceneData* scenes = render_app::builtin_scenes(&n);
  for (uint32_t i = 0; i < n; ++i) printf("%s\r\n", scenes[i].name);
  if (uploaded_scene()) printf("upload (%lu bytes)\r\n", static_cast<unsigned long>(uploaded_size()));
}

// A number of 1..8 hex digits.
bool parse_hex(const char* s, uint32_t* out) {
  uint32_t v = 0, digits = 0;
  for (; *s; ++s, ++digits) {
    const char c = *s;
    const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
    if (d < 0 || digits == 8) return false;
    v = v * 16 + static_cast<uint32_t>(d);
  }
  if (digits == 0) return false;
  *out = v;
  return true;
}

// `upload SIZE CRC32` and `texture SIZE CRC32 [SLOT]`: the size and checksum of what the packets
// bring, and for a texture (`slot` given) its slot, 0 when the line names none.
bool parse_receive(char* rest, uint32_t* size, uint32_t* crc, uint32_t* slot = nullptr) {
  const char* size_text = next_word(&rest);
  const char* crc_text = next_word(&rest);
  const char* slot_text = slot ? next_word(&rest) : nullptr;
  if (slot) *slot = 0;
  // (Any slot number parses: one the console does not have is refused by name, receive_texture.)
  return size_text && crc_text && !next_word(&rest) && parse_uint(size_text, 0, 0x7FFFFFFF, size) &&
         parse_hex(crc_text, crc) && (!slot_text || parse_uint(slot_text, 0, 0xFFFFFFFF, slot));
}

// `set method NAME`: refused here when the raster unit does not build it (RASTER CAPS.METHODS),
// rather than at the next render.
bool set_method(const char* name) {
  using namespace htx::render;
  uint8_t method = 0, n = 16;
  uint32_t span = 0;
  if (strcmp(name, "auto") == 0) {
    method = kMethodAuto;
  } else if (strncmp(name, "subdiv", 6) == 0) {
    if (!parse_uint(name + 6, 2, 64, &span)) {
      error("unknown method ", name);
      return false;
    }
    method = kMethodSubdiv;
    n = static_cast<uint8_t>(span);
  } else {
    method = kMethodCount;
    for (uint32_t m = 0; m < kMethodCount; ++m)
      if (m != kMethodSubdiv && strcmp(name, kMethodNames[m]) == 0) method = static_cast<uint8_t>(m);
    if (method == kMethodCount) {
      error("unknown method ", name);
      return false;
    }
  }
  if (method != kMethodAuto && !((htx::hal::raster_caps().methods >> method) & 1u)) {
    error("this GPU does not build the method ", name);
    return false;
  }
  g_settings.draw.method = method;
  g_settings.draw.subdiv_n = n;
  // The method's own name (`subdiv007` is shown as subdiv7).
  if (method == kMethodSubdiv)
    snprintf(g_settings.method_text, sizeof g_settings.method_text, "subdiv%u", static_cast<unsigned>(n));
  else
    snprintf(g_settings.method_text, sizeof g_settings.method_text, "%s", name);
  return true;
}

// `set filter NAME`: refused here when the texture unit does not build it (TEXTURE CAPS.FILTERS),
// rather than at the next render.
bool set_filter(const char* name) {
  if (strcmp(name, "scene") == 0) {
    g_settings.draw.filter = render_app::kSceneFilter;
    return true;
  }
  for (uint32_t f = 0; f < kFilterCount; ++f) {
    if (strcmp(name, kFilterNames[f]) != 0) continue;
    if (!((htx::hal::texture_caps().filters >> f) & 1u)) {
      error("this GPU does not build the filter ", name);
      return false;
    }
    g_settings.draw.filter = static_cast<uint8_t>(f);
    return true;
  }
  error("unknown filter (nearest, bilinear, trilinear, scene): ", name);
  return false;
}

void cmd_set(char* rest) {
  const char* what = next_word(&rest);
  const char* value = next_word(&rest);
  if (!what || !value || next_word(&rest))
    return error("usage: set method NAME | set tolerance 1/N | set filter NAME");
  if (strcmp(what, "method") == 0) {
    if (!set_method(value)) return;
  } else if (strcmp(what, "tolerance") == 0) {
    uint32_t d = 0;
    if (strncmp(value, "1/", 2) != 0 || !parse_uint(value + 2, 1, 65536, &d))
      return error("tolerance wants 1/N with N = 1..65536, not ", value);
    g_settings.tolerance_denominator = d;
    g_settings.draw.auto_tolerance = htx::render::kOne / d;
  } else if (strcmp(what, "filter") == 0) {
    if (!set_filter(value)) return;
  } else {
    return error("unknown setting ", what);
  }
  printf("ok\r\n");
}

// The scene `render` and `spin` name: a compiled-in one, or `upload`; null with the error printed.
const render_app::SceneData* find_scene(const char* name) {
  if (strcmp(name, "upload") == 0) {
    const render_app::SceneData* up = uploaded_scene();
    if (!up) error("no scene uploaded yet (htx upload)");
    return up;
  }
  uint32_t n = 0;
  const render_app::SceneData* scenes = render_app::builtin_scenes(&n);
  for (uint32_t i = 0; i < n; ++i)
    if (strcmp(scenes[i].name, name) == 0) return &scenes[i];
  error("unknown scene ", name);
  return nullptr;
}

// Draws `scene` with the console's settings into the page not shown and shows it from the next
// frame on (frame_pages.hpp). `over`: drawn over the page drawn last, its colour and depth kept
// (a scene sent in parts, or several scenes in one frame); `hold`: not shown yet (a later render
// that shows, shows it). Prints the error and returns false on failure. A failed render stays off
// the screen, and the frame and figures stay the last good render's: `grab`, `stats` and a
// `render ... over` see that one, not a page the failed one chose (a plan refused, say for a
// filter the GPU does not build, draws nothing; a failure while drawing leaves its page unshown).
bool draw_and_show(const render_app::SceneData& scene, bool checksum = true, bool over = false, bool hold = false) {
  render_app::DrawSettings draw = g_settings.draw;
  draw.time_geometry = false;
  draw.checksum = checksum;
  draw.clear = !over;
  fill_draw_textures(&draw);
  const uint32_t last_page = htx::hal::fb_draw_page();
  if (!over) begin_frame_page(kFlipPolls);
  const render_app::DrawResult result = render_app::draw_scene(scene, draw);
  if (!result.ok) {
    // (Stopped first: a draw that timed out may still be drawing, or clearing, into its page.)
    htx::hal::raster_abort();
    htx::hal::raster_wait_idle(kFlipPolls);
    htx::hal::fb_set_draw_page(last_page);
    // An `over` that failed may have drawn part of itself into that page: its figures are no
    // longer the page's.
    if (over) g_last.ok = false;
    error("render failed: ", result.error);
    return false;
  }
  g_last = result;
  g_last_scene = scene.name;
  if (!hold) present_frame_page(kFlipPolls);
  return true;
}

// `render SCENE [over] [hold]`.
void cmd_render(char* rest) {
  const char* name = next_word(&rest);
  bool over = false, hold = false, bad = !name;
  for (const char* w = name ? next_word(&rest) : nullptr; w; w = next_word(&rest)) {
    if (strcmp(w, "over") == 0 && !over)
      over = true;
    else if (strcmp(w, "hold") == 0 && !hold)
      hold = true;
    else
      bad = true;
  }
  if (bad) return error("usage: render SCENE [over] [hold]");
  const render_app::SceneData* scene = find_scene(name);
  if (!scene || !draw_and_show(*scene, true, over, hold)) return;
  printf("render %s method %s filter %s triangles %lu sent %lu dropped %lu auto_skipped %lu frame_cycles %lu ", name,
         g_settings.method_text, filter_text(g_settings.draw.filter), static_cast<unsigned long>(g_last.stats.triangles),
         static_cast<unsigned long>(g_last.stats.sent),
         static_cast<unsigned long>(g_last.stats.dropped()),
         static_cast<unsigned long>(g_last.stats.auto_skipped),
         static_cast<unsigned long>(g_last.frame_cycles));
  render_app::print_raster_figures(g_last.counters);
  printf(" crc32 %08lx\r\n", static_cast<unsigned long>(g_last.crc));
}

// `spin SCENE [FRAMES] [crc]`: FRAMES renders, frame k turned k / FRAMES of a turn about the
// vertical line through the scene's middle (scene_turn.hpp; the last a whole turn, drawn as the
// scene itself), each shown as it is done; a line a frame (with its CRC-32 if asked: the checksum
// costs more CPU time than drawing the cube), then the rate and the last frame's CRC-32. Any key but a line feed stops it after the frame
// being drawn (the key then begins the next command line).
void cmd_spin(char* rest) {
  const char* name = next_word(&rest);
  const char* count = next_word(&rest);
  const char* crc_word = next_word(&rest);
  if (count && !crc_word && strcmp(count, "crc") == 0) {  // `spin SCENE crc`: FRAMES left out
    crc_word = count;
    count = nullptr;
  }
  uint32_t frames = kSpinDefaultFrames;
  if (!name || next_word(&rest) || (count && !parse_uint(count, 1, kSpinMaxFrames, &frames)) ||
      (crc_word && strcmp(crc_word, "crc") != 0))
    return error("usage: spin SCENE [FRAMES] [crc] (FRAMES = 1..3600, 60 by default)");
  const bool each_crc = crc_word != nullptr;
  const render_app::SceneData* scene = find_scene(name);
  if (!scene) return;
  const TurnAxis axis = scene_turn_axis(*scene);
  const uint64_t t0 = htx::hal::cpu_cycles();
  uint32_t done = 0;
  bool stopped = false;
  for (uint32_t k = 1; k <= frames && !stopped; ++k) {
    const render_app::SceneData turned = k < frames ? turned_scene(*scene, axis, k * 65536u / frames) : *scene;
    if (!draw_and_show(turned, each_crc)) return;
    ++done;
    printf("frame %lu frame_cycles %lu", static_cast<unsigned long>(k), static_cast<unsigned long>(g_last.frame_cycles));
    if (each_crc) printf(" crc32 %08lx", static_cast<unsigned long>(g_last.crc));
    fputs("\r\n", stdout);
    // A line feed is not a key: a terminal that ends lines with CR LF sends the command's LF
    // after the CR that ended it, while the spin has begun. The key that stops it begins the next
    // line (a script's next command arrives while it spins, and must not lose its first byte).
    uint8_t key = 0;
    while (!stopped && htx::hal::uart_try_get(&key)) {
      if (key == '\n') continue;
      stopped = true;
      unread_byte(key);
    }
  }
  const uint64_t cycles = htx::hal::cpu_cycles() - t0;
  printf("spin %s frames %lu%s mcycles ", name, static_cast<unsigned long>(done), stopped ? " (stopped)" : "");
  render_app::print_ratio(cycles, 1'000'000);
  fputs(" fps ", stdout);
  render_app::print_ratio(uint64_t{done} * HTX_SYSCTRL->CLOCK_HZ, cycles);
  if (!each_crc) g_last.crc = render_app::frame_crc32(render_app::kWidth, render_app::kHeight);
  printf(" crc32 %08lx\r\n", static_cast<unsigned long>(g_last.crc));
}

void cmd_grab() { console_app::send_frame(render_app::kWidth, render_app::kHeight); }

void cmd_stats() {
  if (!g_last_scene || !g_last.ok) return error("nothing rendered yet");
  const htx::hal::RasterCounters& c = g_last.counters;
  if (!c.built) return error("this GPU has no raster counters (CAPS.COUNTERS = 0)");
  printf("scene %s busy %lu stall_input %lu stall_setup %lu stall_fragment %lu setup_busy %lu\r\n", g_last_scene,
         static_cast<unsigned long>(c.busy), static_cast<unsigned long>(c.stall_input),
         static_cast<unsigned long>(c.stall_setup), static_cast<unsigned long>(c.stall_fragment),
         static_cast<unsigned long>(c.setup_busy));
  printf("triangles %lu fragments %lu pixels %lu divfree_steps %lu\r\n", static_cast<unsigned long>(c.triangles),
         static_cast<unsigned long>(c.fragments), static_cast<unsigned long>(c.pixels),
         static_cast<unsigned long>(c.divfree_steps));
}

// The commands that take no arguments. An unknown word is reported as unknown, with or without
// words after it; only a known command is told it takes none.
struct CommandWithoutArguments {
  const char* name;
  void (*run)();
};
constexpr CommandWithoutArguments kCommandsWithoutArguments[] = {
    {"help", cmd_help}, {"info", cmd_info}, {"scenes", cmd_scenes}, {"stats", cmd_stats}, {"grab", cmd_grab}};

void run_command_without_arguments(const char* cmd, char* rest) {
  for (const CommandWithoutArguments& c : kCommandsWithoutArguments) {
    if (strcmp(cmd, c.name) != 0) continue;
    if (next_word(&rest)) return error("this command takes no arguments: ", cmd);
    return c.run();
  }
  error("unknown command (type help): ", cmd);
}

}  // namespace

CommandResult run_command(char* line) {
  char* rest = line;
  const char* cmd = next_word(&rest);
  if (!cmd) return CommandResult::kDone;
  if (strcmp(cmd, "quit") == 0) {
    if (!next_word(&rest)) return CommandResult::kQuit;
    error("this command takes no arguments: ", cmd);
    return CommandResult::kDone;
  }
  if (strcmp(cmd, "set") == 0) {
    cmd_set(rest);
  } else if (strcmp(cmd, "render") == 0) {
    cmd_render(rest);
  } else if (strcmp(cmd, "spin") == 0) {
    cmd_spin(rest);
  } else if (strcmp(cmd, "video") == 0) {
    cmd_video(rest);
  } else if (strcmp(cmd, "baud") == 0) {
    cmd_baud(rest);
  } else if (strcmp(cmd, "upload") == 0) {
    uint32_t size = 0, crc = 0;
    if (parse_receive(rest, &size, &crc))
      receive_scene(size, crc);
    else
      error("usage: upload SIZE CRC32 (decimal bytes, hex checksum; `htx upload` sends them)");
  } else if (strcmp(cmd, "texture") == 0) {
    uint32_t size = 0, crc = 0, slot = 0;
    if (parse_receive(rest, &size, &crc, &slot))
      receive_texture(size, crc, slot);
    else
      error("usage: texture SIZE CRC32 [SLOT] (decimal bytes, hex checksum, slot 0 by default; `htx upload` sends "
            "them)");
  } else {
    run_command_without_arguments(cmd, rest);
  }
  return CommandResult::kDone;
}

}  // namespace console_app
