// The console firmware on the simulated SoC, driven by htx's own console tools through the
// pseudo-terminal of `htx sim --uart pty`, as a user would drive a board: commands and their
// errors, a render, a frame download equal to the frame the render firmware leaves on the SoC, a
// scene upload drawing that frame too, refused uploads leaving the scene as it was, and `quit`
// ending the simulation with status 0.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "htx/fw/console_packet.h"
#include "htx/fw/crc32.h"
#include "htx/model/image_io.hpp"
#include "htx/sim/frame_crc.hpp"
#include "htx/sim/video_capture.hpp"
#include "sim_json.hpp"
#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::string field_after(const std::string& text, const std::string& key) {
  const size_t at = text.find(key);
  if (at == std::string::npos) return "";
  const size_t start = at + key.size();
  return text.substr(start, text.find_first_of(" \r\n", start) - start);
}

// A CRC-32 as the console and htx print it: eight lowercase hex digits (field_after gives "" when
// the key is missing, so two failed renders would otherwise compare equal).
::testing::AssertionResult IsCrc32(const std::string& s) {
  if (s.size() == 8 && s.find_first_not_of("0123456789abcdef") == std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << s << "' is not a CRC-32 (eight hex digits)";
}

// A count the console printed: decimal digits, at least one.
::testing::AssertionResult IsCount(const std::string& s) {
  if (!s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << s << "' is not a count";
}

// Reads from the terminal until a whole packet has arrived (or four frames went by without one).
htx::fw::PacketStatus read_packet(int fd, htx::fw::Packet* p) {
  static htx::fw::PacketDecoder decoder;
  for (int frames = 0; frames < 4; ++frames) {
    std::string acc;
    if (!htx::test::read_fd_until(fd, acc, std::string(1, '\0'), 60s)) return htx::fw::kPacketNone;
    for (char c : acc)
      if (htx::fw::packet_feed(&decoder, static_cast<uint8_t>(c), p) == htx::fw::kPacketReady)
        return htx::fw::kPacketReady;
  }
  return htx::fw::kPacketNone;
}

// The pseudo-terminal `htx sim --uart pty` printed (empty if it did not).
std::string pty_of(htx::test::Child& sim) {
  const std::string marker = "htx sim: UART on ";
  if (!sim.read_until("\n", 30s)) return "";
  const size_t at = sim.output().find(marker);
  if (at == std::string::npos) return "";
  return sim.output().substr(at + marker.size(), sim.output().find('\n', at) - at - marker.size());
}

// The console firmware on `htx sim --uart pty`, and `htx console --port PTY -c C ...` against it.
struct ConsoleSim {
  // `extra`: more options for htx sim.
  explicit ConsoleSim(const std::vector<std::string>& extra = {}) : sim(sim_argv(extra)), pty(pty_of(sim)) {}
  static std::vector<std::string> sim_argv(const std::vector<std::string>& extra) {
    std::vector<std::string> argv = {HTX_BIN,  "sim", "--elf",        HTX_FIRMWARE_DIR "/console.elf",
                                     "--uart", "pty", "--max-cycles", "2000000000"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
  }
  htx::test::Child sim;
  const std::string pty;  // empty if it printed none

  // `htx console` on this SoC's pty, typed at (a Child) or given commands (console()).
  std::vector<std::string> console_argv() const {
    return {HTX_BIN, "console", "--port", pty, "--timeout", "60"};
  }
  htx::test::RunResult console(const std::vector<std::string>& commands) const {
    std::vector<std::string> argv = console_argv();
    for (const std::string& c : commands) argv.insert(argv.end(), {"-c", c});
    return htx::test::run_program(argv, 180s);
  }
};

TEST(SystemConsole, CommandsRenderAndGrabThroughThePseudoTerminal) {
  ConsoleSim cs;
  htx::test::Child& sim = cs.sim;
  const std::string& pty = cs.pty;
  ASSERT_FALSE(pty.empty()) << sim.output();

  const auto r = cs.console({"help", "info", "set method bogus", "set tolerance 1/0", "frobnicate", "frobnicate now",
                              "info please", std::string(120, 'x'),
                          "render nosuch", "stats", "render cube", "stats"});
  ASSERT_FALSE(r.timed_out);
  // Every command runs; the refusals make the status 1 (a script learns of them).
  ASSERT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("the console answered 8 of the commands with an error (the first: `set method bogus`)"),
            std::string::npos)
      << r.err;
  // `help`: the console's commands, then what htx itself does with a line.
  EXPECT_NE(r.out.find("commands:\n  help"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("htx console also takes:\n  upload SCENE"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("screen 160x120 rgb565"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("method auto; tolerance 1/16 texel"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown method bogus"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: tolerance wants 1/N with N = 1..65536, not 1/0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown command (type help): frobnicate\n"), std::string::npos) << r.out;
  // An unknown word followed by others is still unknown; a known one is told it takes none.
  EXPECT_EQ(r.out.find("takes no arguments: frobnicate"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("htx> frobnicate now\nerror: unknown command (type help): frobnicate\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("error: this command takes no arguments: info\n"), std::string::npos) << r.out;
  // (refused by htx itself, before sending it: a long line took the serial line's time to refuse)
  EXPECT_NE(r.out.find("error: line longer than 96 characters (not sent)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown scene nosuch"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: nothing rendered yet"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("triangles 6 fragments 7082 pixels 7082"), std::string::npos) << r.out;
  const std::string crc = field_after(r.out.substr(r.out.find("render cube method auto")), "crc32 ");
  ASSERT_TRUE(IsCrc32(crc)) << r.out;

  // A PNG that could not be written is refused before the frame is asked for, so the console is
  // not left sending it: the grab after it works.
  const std::string missing = ::testing::TempDir() + "htx_console_no_such_dir";
  const auto bad = htx::test::run_program({HTX_BIN, "grab", "--port", pty, "--out", missing + "/g.png"}, 60s);
  EXPECT_EQ(bad.status, 1) << bad.err;
  EXPECT_NE(bad.err.find("no directory " + missing + " to write it in"), std::string::npos) << bad.err;

  const std::string png = ::testing::TempDir() + "htx_console_grab.png";
  const auto g = htx::test::run_program({HTX_BIN, "grab", "--port", pty, "--out", png, "--timeout", "60"}, 180s);
  ASSERT_FALSE(g.timed_out);
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_NE(g.out.find("160x120 frame"), std::string::npos) << g.out;
  EXPECT_EQ(field_after(g.out, "crc32 "), crc) << g.out;

  // A scene upload: the cube from the host draws the same frame as the compiled-in cube.
  const auto up = htx::test::run_program({HTX_BIN, "upload", "cube", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(up.status, 0) << up.err;
  EXPECT_NE(up.out.find("upload ok: 816 bytes, 1 meshes, 12 triangles"), std::string::npos) << up.out;
  EXPECT_NE(up.out.find("texture ok: 32x32 rgb565, 6 levels"), std::string::npos) << up.out;
  // Refused scenes leave it as it was: one too large for the store, and one abandoned after a
  // damaged packet (sent by hand: the console asks for it again, then the host gives up).
  const auto big = htx::test::run_program({HTX_BIN, "upload", "tunnel", "--port", pty, "--timeout", "60"}, 180s);
  EXPECT_NE(big.status, 0);
  EXPECT_NE(big.err.find("a scene of 62520 bytes does not fit the store (1..16384)"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("`htx render --engine soc|board` draws it in 5 parts"), std::string::npos) << big.err;
  {
    const int fd = htx::test::open_raw_terminal(pty);
    ASSERT_GE(fd, 0) << "cannot open " << pty << " raw";
    const std::string cmd = "upload 816 0badf00d\r";
    ASSERT_EQ(write(fd, cmd.data(), cmd.size()), static_cast<ssize_t>(cmd.size()));
    std::string got;
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "ready\r\n", 60s)) << got;
    const uint8_t payload[4] = {1, 2, 3, 4};
    uint8_t line[htx::fw::kPacketMaxLine];
    size_t n = htx::fw::packet_encode(htx::fw::kPacketSceneData, 0, payload, sizeof payload, line);
    line[5] ^= 0x01;  // damaged in flight
    ASSERT_EQ(write(fd, line, n), static_cast<ssize_t>(n));
    // The answer: a Nak packet asking for packet 0 again.
    htx::fw::Packet answer{};
    const htx::fw::PacketStatus st = read_packet(fd, &answer);
    ASSERT_EQ(st, htx::fw::kPacketReady);
    EXPECT_EQ(answer.type, htx::fw::kPacketNak);
    ASSERT_EQ(answer.len, 1);
    EXPECT_EQ(answer.payload[0], 0);
    n = htx::fw::packet_encode(htx::fw::kPacketAbort, 0, payload, 1, line);
    ASSERT_EQ(write(fd, line, n), static_cast<ssize_t>(n));
    std::string verdict;
    ASSERT_TRUE(htx::test::read_fd_until(fd, verdict, "htx> ", 60s)) << verdict;
    EXPECT_NE(verdict.find("error: the host abandoned the upload; the scene is unchanged"), std::string::npos) << verdict;
    close(fd);
  }
  {
    // Text sent faster than the console reads it overruns the UART's 16-byte FIFO: the console says
    // so instead of running a line with characters missing, and keeps working.
    const int fd = htx::test::open_raw_terminal(pty);
    ASSERT_GE(fd, 0) << "cannot open " << pty << " raw";
    std::string burst;
    for (int i = 0; i < 20; ++i) burst += "info\r";
    ASSERT_EQ(write(fd, burst.data(), burst.size()), static_cast<ssize_t>(burst.size()));
    std::string got;
    EXPECT_TRUE(htx::test::read_fd_until(fd, got, "error: input arrived faster than the console reads it", 60s))
        << got;
    close(fd);
  }
  const std::string png2 = ::testing::TempDir() + "htx_console_grab_upload.png";
  const auto again = cs.console({"scenes", "render upload", "grab " + png2, "grab"});
  EXPECT_NE(again.status, 0);  // the last line: grab without a file
  EXPECT_NE(again.err.find("usage: grab FRAME.png"), std::string::npos) << again.err;
  EXPECT_EQ(field_after(again.out, "packets, crc32 "), crc) << again.out;
  EXPECT_NE(again.out.find("upload (816 bytes)"), std::string::npos) << again.out;
  EXPECT_EQ(field_after(again.out.substr(again.out.find("render upload method")), "crc32 "), crc) << again.out;

  const auto q = cs.console({"quit"});
  EXPECT_EQ(q.status, 0) << q.err;
  EXPECT_EQ(sim.wait(60s), 0) << "htx sim should end with the console's status 0";

  // The render firmware's cube on the SoC, left in the framebuffer at its exit: the same frame.
  const std::string ref = ::testing::TempDir() + "htx_console_render_cube.png";
  const auto s = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/render_cube.elf", "--frame", ref, "--max-cycles", "200000000"},
      180s);
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NE(s.out.find("crc32 " + crc), std::string::npos) << s.out;
  const auto cmp = htx::test::run_program({HTX_BIN, "compare", png, ref}, 60s);
  ASSERT_EQ(cmp.status, 0) << cmp.err;
  EXPECT_NE(cmp.out.find("differing_pixels 0"), std::string::npos) << cmp.out;
}

// A client that ends in the middle of an upload (here an upload begun by hand, then the port
// closed) leaves the console receiving packets; the next htx client's Abort ends that at once, so
// its command is answered within a 10 s --timeout, where it used to wait out the console's own
// silence timeout (most of a minute on the simulator) and fail.
TEST(SystemConsole, TheNextClientEndsAnUploadTheLastOneLeft) {
  ConsoleSim cs;
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  {
    const int fd = htx::test::open_raw_terminal(cs.pty);
    ASSERT_GE(fd, 0) << "cannot open " << cs.pty << " raw";
    std::string got;
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "htx> ", 60s)) << got;  // booted: the FIFO is read
    const std::string cmd = "upload 816 0badf00d\r";
    ASSERT_EQ(write(fd, cmd.data(), cmd.size()), static_cast<ssize_t>(cmd.size()));
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "ready\r\n", 60s)) << got;
    close(fd);
  }
  const auto next = htx::test::run_program(
      {HTX_BIN, "console", "--port", cs.pty, "--timeout", "10", "-c", "scenes", "-c", "quit"}, 120s);
  ASSERT_FALSE(next.timed_out);
  EXPECT_EQ(next.status, 0) << next.out << next.err;
  EXPECT_NE(next.out.find("htx> scenes\n"), std::string::npos) << next.out;
  EXPECT_NE(next.out.find("cube"), std::string::npos) << next.out;
  EXPECT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
}

// Ctrl-C in `htx console` while the console works stops the command as a typed line does (a spin
// ends after its frame) and the session goes on; until 2026-12-06 it ended htx and left the console
// spinning with no client.
TEST(SystemConsole, CtrlCStopsASpinAndTheSessionGoesOn) {
  ConsoleSim cs;
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  htx::test::Child console(cs.console_argv(), true);
  ASSERT_TRUE(console.read_until("htx> ", 60s)) << console.output();
  console.write_input("spin floor 3600\n");
  ASSERT_TRUE(console.read_until("frame 2 frame_cycles", 60s)) << console.output();
  console.send_signal(SIGINT);
  ASSERT_TRUE(console.read_until("spin floor frames ", 60s)) << console.output();
  EXPECT_NE(console.output().find("(stopped)"), std::string::npos) << console.output();
  console.write_input("info\n");
  ASSERT_TRUE(console.read_until("serial 115384 baud", 60s)) << console.output();
  console.write_input("quit\n");
  console.close_input();
  EXPECT_EQ(console.wait(60s), 0) << console.output();
  EXPECT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
}

// One client at a time: a second htx client on the pty is refused at once, where its bytes and
// the first one's answers used to mix (a grab "damaged", an upload waiting out its timeout). A
// command with a control byte is refused before it is sent: a Ctrl-C in it ended the console's
// line early and put every later answer one command out of step, and a zero made the console skip
// up to 251 bytes. The console answers in step after both.
TEST(SystemConsole, OneClientAtATimeAndNoControlBytesInACommand) {
  ConsoleSim cs;
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  {
    htx::test::Child first(cs.console_argv(), true);
    ASSERT_TRUE(first.read_until("htx> ", 60s)) << first.output();
    const auto second = cs.console({"info"});
    EXPECT_EQ(second.status, 1) << second.out;
    EXPECT_NE(second.err.find("is in use by another htx client"), std::string::npos) << second.err;
    const auto grab = htx::test::run_program(
        {HTX_BIN, "grab", "--port", cs.pty, "--out", ::testing::TempDir() + "htx_console_locked.png"}, 60s);
    EXPECT_EQ(grab.status, 1) << grab.out;
    EXPECT_NE(grab.err.find("is in use by another htx client"), std::string::npos) << grab.err;
    first.write_input("scenes\n");
    ASSERT_TRUE(first.read_until("cube", 60s)) << first.output();
    // Its input is a pipe, not a terminal that echoes: the line is shown after the prompt.
    EXPECT_NE(first.output().find("htx> scenes\n"), std::string::npos) << first.output();
    first.close_input();
    EXPECT_EQ(first.wait(60s), 0) << first.output();
  }
  const auto control = cs.console({"foo\x03scenes", "help"});
  EXPECT_EQ(control.status, 1) << control.out;
  EXPECT_NE(control.err.find("a command holds no control characters (byte 3)"), std::string::npos) << control.err;
  const auto after = cs.console({"help", "info"});
  ASSERT_EQ(after.status, 0) << after.err;
  // In step: help's answer after `help`, info's after `info`.
  const size_t help = after.out.find("htx> help\ncommands:");
  const size_t info = after.out.find("htx> info\nhypertex console");
  EXPECT_NE(help, std::string::npos) << after.out;
  EXPECT_NE(info, std::string::npos) << after.out;
  EXPECT_LT(help, info) << after.out;
  EXPECT_EQ(cs.console({"quit"}).status, 0);
  EXPECT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
}

// `htx console` typed at, as a person does: a spin's frames show as they are drawn, a line typed
// while it runs stops it after its frame and then runs (shown after the prompt), and a line typed
// while a render works waits for it, whole, though longer than the console's 16-byte receive
// FIFO. Fails when htx waits for a command's whole answer (nothing shows before the spin's end,
// and a 3,600-frame spin of the floor takes minutes), or when it sends the typed line while the
// console is busy (the console would read it only after the render, its FIFO long full).
TEST(SystemConsole, TypedLinesStopASpinAndRunAfterIt) {
  ConsoleSim cs;
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  htx::test::Child console(cs.console_argv(), true);
  ASSERT_TRUE(console.read_until("htx> ", 60s)) << console.output();
  // A local file that does not load is the line's error; the session goes on.
  console.write_input("texture /no/such/image.png\n");
  ASSERT_TRUE(console.read_until("error: cannot load image '/no/such/image.png'", 60s)) << console.output();
  console.write_input("spin floor 3600\n");
  ASSERT_TRUE(console.read_until("frame 2 frame_cycles", 60s)) << console.output();
  EXPECT_EQ(console.output().find("spin floor frames"), std::string::npos) << "the spin ended early";
  console.write_input("info\n");
  ASSERT_TRUE(console.read_until("serial 115384 baud", 60s)) << console.output();
  const std::string& out = console.output();
  const size_t stopped = out.find("(stopped)");
  ASSERT_NE(stopped, std::string::npos) << out;
  // The spin's summary names the frames drawn (a few, not 3,600), then the typed line runs.
  const size_t frames = out.find("spin floor frames ");
  ASSERT_NE(frames, std::string::npos) << out;
  EXPECT_LT(std::stoul(out.substr(frames + 18)), 100u) << out;
  EXPECT_NE(out.find("htx> info\nhypertex console", stopped), std::string::npos) << out;
  // A line typed while a render works runs after it, whole (18 characters).
  console.write_input("render floor\n");
  std::this_thread::sleep_for(300ms);  // the floor's render takes seconds of the simulation
  console.write_input("set tolerance 1/64\n");
  ASSERT_TRUE(console.read_until("render floor method auto", 60s)) << console.output();
  console.write_input("info\n");
  ASSERT_TRUE(console.read_until("tolerance 1/64 texel", 60s)) << console.output();
  const std::string after = console.output().substr(console.output().find("render floor method auto"));
  EXPECT_NE(after.find("htx> set tolerance 1/64\nok\n"), std::string::npos) << after;
  EXPECT_EQ(after.find("error"), std::string::npos) << after;
  console.write_input("quit\n");
  console.close_input();
  EXPECT_EQ(console.wait(60s), 0) << console.output();
  EXPECT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
}

// `htx console` at a terminal, as a person types: lines are edited with libedit, and the up arrow
// brings back an earlier line (the session's history), here `info` after a `set method`. Fails
// without line editing: the arrow's escape sequence goes to the console as text.
TEST(SystemConsole, AtATerminalTheUpArrowRecallsAnEarlierLine) {
  ConsoleSim cs;
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  htx::test::Child console(cs.console_argv(),
                          htx::test::Child::Terminal{{"TERM=xterm"}});
  ASSERT_TRUE(console.read_until("htx> ", 60s)) << console.output();
  console.write_input("info\r");
  ASSERT_TRUE(console.read_until("method auto; tolerance", 60s)) << console.output();
  console.write_input("set method affine\r");
  // The arrows are typed once the next prompt shows: libedit puts the terminal in raw mode before
  // it prints the prompt, and keys typed before that are the terminal's to echo and buffer as text.
  const auto prompt_after = [&console](const std::string& answer) {
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (std::chrono::steady_clock::now() < deadline) {
      const size_t at = console.output().find(answer);
      if (at != std::string::npos && console.output().find("htx> ", at) != std::string::npos) return true;
      console.read_until("htx> set method affine\x01", 100ms);  // takes what has come
    }
    return false;
  };
  ASSERT_TRUE(prompt_after("ok")) << console.output();
  console.write_input("\x1b[A\x1b[A\r");  // up, up: `info` again
  ASSERT_TRUE(console.read_until("method affine; tolerance", 60s)) << console.output();
  EXPECT_EQ(console.output().find("unknown command"), std::string::npos) << console.output();
  console.write_input("quit\r");
  EXPECT_EQ(console.wait(60s), 0) << console.output();
  EXPECT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
}

// `baud N` switches the serial line after its `ok` (htx console switches the port with it, and the
// harness's end of the line follows the UART's divisor, as a terminal set to match would): rates
// the UART cannot make within 2 % at 12 MHz, and 3 Mbaud, faster than the console reads an upload,
// are refused and leave the line as it was; after the switch to 1 Mbaud commands, a render and a
// grab work at the new rate, and back to 115,200.
TEST(SystemConsole, BaudSwitchesTheLineBothWays) {
  ConsoleSim cs;
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  const auto r = cs.console({"baud 250000", "info", "quit now", "baud 5000000", "baud 7", "baud 3000000",
                             "baud 1000000", "info", "render cube"});
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 1) << r.out << r.err;  // five refusals, every command run
  EXPECT_NE(r.err.find("answered 5 of the commands with an error (the first: `baud 250000`)"), std::string::npos)
      << r.err;
  // A rate the UART makes but this end's port cannot take is refused before the console is asked,
  // so both ends stay at 115,200 (the console would otherwise have switched alone).
  EXPECT_NE(r.out.find("htx> baud 250000\nbaud 250000: want 9600, 19200"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("htx> info\nhypertex console"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("serial 115384 baud"), std::string::npos) << r.out;
  // `quit` takes no words after it: an error, and the console goes on.
  EXPECT_NE(r.out.find("htx> quit now\nerror: this command takes no arguments: quit\n"), std::string::npos) << r.out;
  // Rates no port takes are refused by htx; 3 Mbaud, which ports take, by the console (below, the
  // console's own refusals of the others, sent to it directly).
  EXPECT_NE(r.out.find("htx> baud 5000000\nbaud 5000000: want 9600"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("htx> baud 7\nbaud 7: want 9600"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: 3000000 baud is faster than the console reads an upload (6 clocks a bit or more: up "
                       "to 2000000 baud at 12000000 Hz)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("htx> baud 1000000\nbaud 1000000\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at 12000000 Hz, serial 1000000 baud"), std::string::npos) << r.out;
  const std::string crc = field_after(r.out.substr(r.out.find("render cube method auto")), "crc32 ");
  ASSERT_TRUE(IsCrc32(crc)) << r.out;
  const std::string png = ::testing::TempDir() + "htx_console_baud_grab.png";
  const auto g = htx::test::run_program({HTX_BIN, "grab", "--port", cs.pty, "--out", png, "--timeout", "60"}, 180s);
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_EQ(field_after(g.out, "crc32 "), crc) << g.out;
  std::filesystem::remove(png);
  const auto back = cs.console({"baud 115200", "info", "quit"});
  EXPECT_EQ(back.status, 0) << back.err;
  EXPECT_NE(back.out.find("serial 115384 baud"), std::string::npos) << back.out;
  ASSERT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
}

// The screen: the console turns the video on at boot, so after a render and enough serial output
// for two frames (each `info` is some 300,000 clocks of UART at 115,200 baud), `htx sim --screen`
// holds the frame the render left, each framebuffer pixel a 4 x 4 block (the framebuffer itself
// from --frame).
TEST(SystemConsole, ScreenShowsTheRenderedFrameScaled) {
  const std::string screen = ::testing::TempDir() + "htx_console_screen.png";
  const std::string frame = ::testing::TempDir() + "htx_console_screen_frame.png";
  ConsoleSim cs({"--screen", screen, "--frame", frame});
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  const auto r = cs.console(
      {"video", "video dim", "video off", "info", "video on", "render cube", "info", "info", "info", "quit"});
  ASSERT_EQ(r.status, 1) << r.err;  // the two usage errors
  EXPECT_NE(r.err.find("answered 2 of the commands with an error (the first: `video`)"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("htx> video\nerror: usage: video on|off\nhtx> video dim\nerror: usage: video on|off"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("video 640x480 60 Hz showing 160x120 x4: off"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("video 640x480 60 Hz showing 160x120 x4: on"), std::string::npos) << r.out;
  // Triple buffering: the cube is drawn into page 1 (neither shown nor waiting to be) while page
  // 0 is shown, then shown from the next frame's start (`info` prints the page shown); the frame
  // `--frame` saves is page 1's.
  EXPECT_NE(r.out.find("x4: off, frame "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", page 0 of 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", page 1 of 3"), std::string::npos) << r.out;
  ASSERT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
  const htx::Image s = htx::load_image(screen);
  const htx::Image f = htx::load_image(frame);
  ASSERT_EQ(s.width, 640);
  ASSERT_EQ(s.height, 480);
  ASSERT_EQ(f.width, 160);
  ASSERT_EQ(f.height, 120);
  int differing = 0, lit = 0;
  for (int y = 0; y < 480; ++y) {
    for (int x = 0; x < 640; ++x) {
      const size_t si = 4 * (static_cast<size_t>(y) * 640 + x);
      const size_t fi = 4 * (static_cast<size_t>(y / 4) * 160 + x / 4);
      differing += !std::equal(&s.rgba[si], &s.rgba[si] + 4, &f.rgba[fi]);
      lit += s.rgba[si] | s.rgba[si + 1] | s.rgba[si + 2] ? 1 : 0;
    }
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(lit, 7082 * 16 / 2) << "the cube's fragments are on the screen";
}

// `spin cube 4 crc`: four frames a quarter turn apart, each shown as it is drawn; the last is a
// whole turn, the scene itself, so its CRC-32 is `render cube`'s, and the half turn's is another.
TEST(SystemConsole, SpinTurnsTheSceneAndEndsWhereItStarted) {
  ConsoleSim cs;
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  const auto r = cs.console({"spin", "spin cube 0", "spin cube 3601", "spin cube 2 3", "spin cube 2 crc x",
                             "spin nosuch", "render cube", "spin cube 4 crc", "spin cube 2"});
  ASSERT_EQ(r.status, 1) << r.err;  // the six refusals
  EXPECT_NE(r.err.find("answered 6 of the commands with an error (the first: `spin`)"), std::string::npos) << r.err;
  const std::string usage = "error: usage: spin SCENE [FRAMES] [crc] (FRAMES = 1..3600, 60 by default)";
  size_t usages = 0;
  for (size_t at = r.out.find(usage); at != std::string::npos; at = r.out.find(usage, at + 1)) ++usages;
  EXPECT_EQ(usages, 5u) << r.out;
  EXPECT_NE(r.out.find("error: unknown scene nosuch"), std::string::npos) << r.out;
  const auto crc_after = [&](const std::string& key) {
    const size_t at = r.out.find(key);
    return at == std::string::npos ? std::string() : field_after(r.out.substr(at), "crc32 ");
  };
  const std::string rendered = crc_after("render cube method");
  ASSERT_TRUE(IsCrc32(rendered)) << r.out;
  EXPECT_EQ(crc_after("frame 4 frame_cycles"), rendered) << r.out;
  const std::string half = crc_after("frame 2 frame_cycles");
  ASSERT_TRUE(IsCrc32(half)) << r.out;
  EXPECT_NE(half, rendered) << r.out;
  const std::string quarter = crc_after("frame 1 frame_cycles");
  ASSERT_TRUE(IsCrc32(quarter)) << r.out;
  EXPECT_NE(quarter, half) << r.out;
  EXPECT_EQ(crc_after("spin cube frames 4 mcycles "), rendered) << r.out;
  // Without `crc` the frames' lines have none; the summary has the last frame's.
  const size_t two = r.out.find("htx> spin cube 2\n");
  ASSERT_NE(two, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frame 2 frame_cycles ", two), std::string::npos) << r.out;
  EXPECT_GT(r.out.find("crc32", two), r.out.find("spin cube frames 2 mcycles ", two)) << r.out;
  EXPECT_EQ(r.out.find("(stopped)"), std::string::npos) << r.out;
  {
    // From a terminal: a CR LF line end does not stop the spin (its LF arrives after the spin
    // began), and a key does, after the frame being drawn.
    const int fd = htx::test::open_raw_terminal(cs.pty);
    ASSERT_GE(fd, 0) << "cannot open " << cs.pty << " raw";
    const std::string crlf = "spin cube 3\r\n";
    ASSERT_EQ(write(fd, crlf.data(), crlf.size()), static_cast<ssize_t>(crlf.size()));
    std::string got;
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "htx> ", 60s)) << got;
    EXPECT_NE(got.find("spin cube frames 3 mcycles"), std::string::npos) << got;
    const std::string long_spin = "spin cube 3600\r";
    ASSERT_EQ(write(fd, long_spin.data(), long_spin.size()), static_cast<ssize_t>(long_spin.size()));
    got.clear();
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "frame 1 frame_cycles", 60s)) << got;
    // The key that stops it begins the next line: "i" then "nfo" runs `info`.
    ASSERT_EQ(write(fd, "i", 1), 1);
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "htx> i", 60s)) << got;
    EXPECT_NE(got.find(" (stopped) mcycles"), std::string::npos) << got;
    EXPECT_EQ(got.find("frame 10 frame_cycles"), std::string::npos) << got;
    ASSERT_EQ(write(fd, "nfo\r", 4), 4);
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "page ", 60s)) << got;
    EXPECT_NE(got.find("htx> info\r\n"), std::string::npos) << got;
    close(fd);
  }
  EXPECT_EQ(cs.console({"quit"}).status, 0);
  ASSERT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
}

// `htx sim --json` on the console firmware with `stdin_file` as its standard input.
htx::test::RunResult console_on_stdin(const std::string& stdin_file, uint64_t max_cycles) {
  const std::string cmd = std::string(HTX_BIN) + " sim --elf " HTX_FIRMWARE_DIR "/console.elf --uart stdio --json --max-cycles " +
                          std::to_string(max_cycles) + " < " + stdin_file;
  return htx::test::run_program({"/bin/sh", "-c", cmd}, 180s);
}

// The same with `script` written to a file of its own for stdin.
htx::test::RunResult console_script(const std::string& script) {
  const std::string file = ::testing::TempDir() + "htx_console_script_" + std::to_string(getpid()) + ".txt";
  std::ofstream(file) << script;
  auto r = console_on_stdin(file, 200'000'000);
  std::filesystem::remove(file);
  return r;
}

// A script on `htx sim --uart stdio`'s standard input (a file or a pipe) is fed as fast as the UART's
// 16-byte receive FIFO has room, so lines queued behind a render are not lost (at the line's rate
// they overran the FIFO: the console dropped them); a command that arrives during a spin stops it
// and runs whole.
TEST(SystemConsole, AScriptOnStandardInputLosesNothing) {
  const auto r = console_script("render cube\nset method recip_nr\nrender cube\nset tolerance 1/8\nset method auto\n"
                                "spin cube 3\ninfo\nquit\n");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("error:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("render cube method auto"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("render cube method recip_nr"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spin cube frames 1 (stopped)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("htx> info\r\nhypertex"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tolerance 1/8"), std::string::npos) << r.out;
}

// The console's own refusals of rates its UART cannot make within 2 % at 12 MHz (htx console
// refuses these before asking it, so they are sent here as a script): the line stays as it was.
TEST(SystemConsole, BaudRefusesRatesTheUartCannotMake) {
  const auto r = console_script("baud 5000000\nbaud 7\nbaud 0\ninfo\nquit\n");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("error: 5000000 baud is not one this UART makes at 12000000 Hz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: 7 baud is not one this UART makes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("htx> baud 0\r\nerror: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("serial 115384 baud"), std::string::npos) << r.out;
}

// Small things of the command line: a subdiv method given with leading zeros is shown by its own
// name; a texture larger than the store is refused before `ready`; a texture slot beyond 255 is
// refused by name like any slot the console lacks (it was a
// usage error); backspacing a line past the limit back within it takes back the characters beyond
// it first (the line then runs); `spin SCENE crc` leaves FRAMES out (here stopped after its first
// frame by the next line).
TEST(SystemConsole, LineEditsSlotsMethodNamesAndSpinWithoutFrames) {
  const std::string long_line = std::string(90, 'z') + std::string(10, 'y') + std::string(8, '\b');
  const auto r = console_script("set method subdiv007\ninfo\ntexture 100 0 256\ntexture 8204 0\n" + long_line +
                                "\nspin cube crc\ninfo\nquit\n");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("method subdiv7; tolerance"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: texture slot 256 is not one of the console's 0..3; nothing was received"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("error: a texture of 8204 bytes does not fit the store (1..2060)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown command (type help): " + std::string(90, 'z') + "yy\r\n"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("line longer than"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frame 1 frame_cycles "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spin cube frames 1 (stopped)"), std::string::npos) << r.out;
  const size_t frame = r.out.find("frame 1 frame_cycles ");
  EXPECT_NE(r.out.substr(frame, r.out.find('\r', frame) - frame).find(" crc32 "), std::string::npos) << r.out;
}

// A script without `quit`: the run ends once the script has ended and the console waits for its
// next line (status 0, stop reason input_ended), not at --max-cycles; a spin on the last line,
// which looks for a key once a frame, still draws every frame first. An empty stdin is no script.
TEST(SystemConsole, AScriptWithoutQuitEndsWithItsInput) {
  const auto r = console_script("render cube\ninfo\nspin cube 3\n");
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("error:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("render cube method auto"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("htx> info\r\nhypertex"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spin cube frames 3 mcycles"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"reason\":\"input_ended\""), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("standard input ended"), std::string::npos) << r.err;
  // Ended while waiting, long before the limit: the whole session is a few million clocks.
  const auto json = htx::test::last_json_line(r.out);
  EXPECT_LT(json.at("cycles").get<uint64_t>(), 20'000'000ull) << r.out;

  // An empty stdin is no script: the console waits on, and the run ends at its cycle limit.
  const auto e = console_on_stdin("/dev/null", 3'000'000);
  EXPECT_EQ(e.status, 124) << e.out << e.err;
  EXPECT_NE(e.out.find("\"reason\":\"cycle_limit\""), std::string::npos) << e.out;
}

// The CRC-32 the firmware prints for the frame a screen picture (640 x 480 RGBA) shows; "" when a
// 4 x 4 block is not one colour, which no whole frame of the framebuffer shows.
std::string screen_frame_crc(const htx::Image& img) {
  std::vector<uint32_t> picture;
  for (size_t i = 0; i + 3 < img.rgba.size(); i += 4)
    picture.push_back((uint32_t{img.rgba[i]} << 16) | (uint32_t{img.rgba[i + 1]} << 8) | img.rgba[i + 2]);
  const std::vector<uint16_t> frame = htx::sim::frame_from_screen(picture, 640, 480, 4);
  if (frame.empty()) return "";
  char hex[16];
  std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(htx::sim::frame_crc32(frame)));
  return hex;
}

// Double buffering seen on the screen: every picture the video showed (`htx sim --screen-frames`)
// during a render and a spin is a whole frame the firmware drew (its CRC-32 is one the console
// printed) or the black of the memory before the first, never one being cleared or drawn.
TEST(SystemConsole, TheScreenShowsOnlyWholeFrames) {
  // (a directory of this process's own: the test reads back every file in it)
  const std::string dir = ::testing::TempDir() + "htx_console_screen_frames_" + std::to_string(getpid());
  std::filesystem::remove_all(dir);
  ConsoleSim cs({"--screen-frames", dir});
  ASSERT_FALSE(cs.pty.empty()) << cs.sim.output();
  const auto r = cs.console({"render cube", "spin cube 4 crc", "info", "info", "quit"});
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(cs.sim.wait(60s), 0) << cs.sim.output();
  std::vector<std::string> drawn = {screen_frame_crc(htx::Image{640, 480, std::vector<uint8_t>(640 * 480 * 4, 0)})};
  for (size_t at = r.out.find("crc32 "); at != std::string::npos; at = r.out.find("crc32 ", at + 1))
    drawn.push_back(r.out.substr(at + 6, 8));
  ASSERT_EQ(drawn.size(), 1u + 1u + 4u + 1u) << r.out;  // black, render, four frames, the summary
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  std::string shown;  // every picture's CRC-32, for the failure messages
  for (const std::string& f : files) {
    const htx::Image img = htx::load_image(f);
    ASSERT_EQ(img.width, 640) << f;
    ASSERT_EQ(img.height, 480) << f;
    const std::string crc = screen_frame_crc(img);
    shown += f + " " + (crc.empty() ? "(blocks not one colour)" : crc) + "\n";
    EXPECT_NE(std::find(drawn.begin(), drawn.end(), crc), drawn.end()) << f << " shows a frame never drawn";
  }
  // Black, the render, and each frame of the spin (each is drawn in about three of the video's
  // frames, so each is shown); equal neighbours are written once.
  EXPECT_GE(files.size(), 5u);
  if (HasFailure()) ADD_FAILURE() << "pictures:\n" << shown << "console:\n" << r.out << "sim:\n" << cs.sim.output();
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

// An image whose bottom row is texel row 0, from f(x, v) -> RGBA.
template <typename F>
void write_texture_png(const std::string& path, int w, int h, F f) {
  htx::Image img{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::array<uint8_t, 4> c = f(x, h - 1 - y);
      std::copy(c.begin(), c.end(), &img.rgba[4 * (static_cast<size_t>(y) * w + x)]);
    }
  htx::write_png(path, img);
}

// Texture upload: the render firmware's checkerboard sent as an image draws exactly the frame the
// console's own checkerboard draws; another texture draws another frame; refused textures (too
// large, not a power of two, damaged in the packed form) leave the texture as it was.
TEST(SystemConsole, TextureUploadDrawsWithTheUploadedTexture) {
  ConsoleSim cs;
  htx::test::Child& sim = cs.sim;
  const std::string& pty = cs.pty;
  ASSERT_FALSE(pty.empty()) << sim.output();
  const auto render_crc = [](const std::string& out) {
    const size_t at = out.rfind("render cube method");
    return at == std::string::npos ? std::string() : field_after(out.substr(at), "crc32 ");
  };
  const auto boot = cs.console({"info", "render cube"});
  ASSERT_EQ(boot.status, 0) << boot.err;
  EXPECT_NE(boot.out.find("texture 0: 32x32 rgb565 (checkerboard)"), std::string::npos) << boot.out;
  const std::string checker_crc = render_crc(boot.out);
  ASSERT_TRUE(IsCrc32(checker_crc)) << boot.out;

  // soc_texture.cpp's checkerboard: white and the model's ink in 4-texel squares.
  const std::string checker = ::testing::TempDir() + "htx_console_checker.png";
  write_texture_png(checker, 32, 32, [](int x, int v) {
    return ((x >> 2) ^ (v >> 2)) & 1 ? std::array<uint8_t, 4>{40, 60, 140, 255} : std::array<uint8_t, 4>{255, 255, 255, 255};
  });
  const auto same = cs.console({"texture " + checker, "info", "render cube"});
  ASSERT_EQ(same.status, 0) << same.err;
  EXPECT_NE(same.out.find("texture ok: 32x32 rgb565, 6 levels"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find("texture 0: 32x32 rgb565 (uploaded)"), std::string::npos) << same.out;
  EXPECT_EQ(render_crc(same.out), checker_crc) << same.out;

  // Another texture, another shape and format, through `htx upload --texture`.
  const std::string ramp = ::testing::TempDir() + "htx_console_ramp.png";
  write_texture_png(ramp, 16, 64, [](int x, int v) {
    return std::array<uint8_t, 4>{static_cast<uint8_t>(x * 16), static_cast<uint8_t>(v * 4), 200, 255};
  });
  const auto up = htx::test::run_program(
      {HTX_BIN, "upload", "--texture", ramp, "--format", "rgba4444", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(up.status, 0) << up.err;
  EXPECT_NE(up.out.find("texture ok: 16x64 rgba4444, 7 levels"), std::string::npos) << up.out;
  const auto drawn = cs.console({"render cube"});
  ASSERT_EQ(drawn.status, 0) << drawn.err;
  const std::string ramp_crc = render_crc(drawn.out);
  ASSERT_TRUE(IsCrc32(ramp_crc)) << drawn.out;
  EXPECT_NE(ramp_crc, checker_crc);

  // Refused: too large for a slot and sides not powers of two (both before the port opens; the
  // console's own refusal of a size beyond its store: LineEditsSlotsMethodNamesAndSpinWithoutFrames),
  // and a packed texture damaged inside (its CRC-32 right) sent by hand.
  const std::string big = ::testing::TempDir() + "htx_console_big.png";
  write_texture_png(big, 64, 64, [](int, int) { return std::array<uint8_t, 4>{1, 2, 3, 255}; });
  const auto too_big = htx::test::run_program({HTX_BIN, "upload", "--texture", big, "--port", pty, "--timeout", "60"}, 180s);
  EXPECT_NE(too_big.status, 0);
  EXPECT_NE(too_big.err.find("is 64x64: a console texture slot holds at most 1024 texels"), std::string::npos)
      << too_big.err;
  EXPECT_EQ(too_big.out.find("upload:"), std::string::npos) << "sent: " << too_big.out;
  const std::string odd = ::testing::TempDir() + "htx_console_odd.png";
  write_texture_png(odd, 24, 16, [](int, int) { return std::array<uint8_t, 4>{1, 2, 3, 255}; });
  const auto not_pow2 = htx::test::run_program({HTX_BIN, "upload", "--texture", odd, "--port", pty}, 60s);
  EXPECT_NE(not_pow2.status, 0);
  EXPECT_NE(not_pow2.err.find("is 24x16; sides must be powers of two in 8..256"), std::string::npos) << not_pow2.err;
  {
    std::vector<uint8_t> packed(12 + 2 * 64, 0);
    const char header[] = {'H', 'T', 'X', 'T', 1, 0, 3, 3, 0};
    std::copy(header, header + sizeof header, packed.begin());
    packed[8] = 2;  // RGBA8888: not a 16-bit format
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08x", htx::fw::crc32(packed.data(), packed.size()));
    const int fd = htx::test::open_raw_terminal(pty);
    ASSERT_GE(fd, 0) << "cannot open " << pty << " raw";
    const std::string cmd = "texture " + std::to_string(packed.size()) + " " + crc + "\r";
    ASSERT_EQ(write(fd, cmd.data(), cmd.size()), static_cast<ssize_t>(cmd.size()));
    std::string got;
    ASSERT_TRUE(htx::test::read_fd_until(fd, got, "ready\r\n", 60s)) << got;
    uint8_t line[htx::fw::kPacketMaxLine];
    const size_t n = htx::fw::packet_encode(htx::fw::kPacketSceneData, 0, packed.data(), packed.size(), line);
    ASSERT_EQ(write(fd, line, n), static_cast<ssize_t>(n));
    std::string verdict;
    ASSERT_TRUE(htx::test::read_fd_until(fd, verdict, "htx> ", 60s)) << verdict;
    EXPECT_NE(verdict.find("error: not a valid texture (the format is not RGB565 or RGBA4444); the texture is unchanged"),
              std::string::npos)
        << verdict;
    close(fd);
  }
  const auto after = cs.console({"info", "render cube"});
  ASSERT_EQ(after.status, 0) << after.err;
  EXPECT_NE(after.out.find("texture 0: 16x64 rgba4444 (uploaded)"), std::string::npos) << after.out;
  EXPECT_EQ(render_crc(after.out), ramp_crc) << after.out;

  // A scene without its texture keeps the ramp: the uploaded cube draws the ramp's frame.
  const auto bare = htx::test::run_program(
      {HTX_BIN, "upload", "cube", "--no-texture", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(bare.status, 0) << bare.err;
  EXPECT_EQ(bare.out.find("texture ok"), std::string::npos) << bare.out;
  const auto bare_drawn = cs.console({"render upload"});
  ASSERT_EQ(bare_drawn.status, 0) << bare_drawn.err;
  EXPECT_EQ(field_after(bare_drawn.out, "crc32 "), ramp_crc) << bare_drawn.out;
  // An OBJ sends its MTL's texture (8 x 16, level 0) the way an image is sent: the same frame.
  const auto obj = htx::test::run_program(
      {HTX_BIN, "upload", HTX_TEST_DATA_DIR "/quad.obj", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(obj.status, 0) << obj.err;
  EXPECT_NE(obj.out.find("texture ok: 8x16 rgb565, 5 levels"), std::string::npos) << obj.out;
  const auto obj_drawn = cs.console({"render upload"});
  ASSERT_EQ(obj_drawn.status, 0) << obj_drawn.err;
  const std::string obj_crc = field_after(obj_drawn.out, "crc32 ");
  ASSERT_TRUE(IsCrc32(obj_crc)) << obj_drawn.out;
  const std::string obj_fragments = field_after(obj_drawn.out, "fragments ");
  ASSERT_TRUE(IsCount(obj_fragments)) << obj_drawn.out;
  EXPECT_GT(std::stoul(obj_fragments), 0u) << obj_drawn.out;
  EXPECT_NE(obj_crc, ramp_crc) << "the quad draws a frame of its own";
  const auto png = htx::test::run_program(
      {HTX_BIN, "upload", "--texture", HTX_TEST_DATA_DIR "/checker8x16.png", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(png.status, 0) << png.err;
  const auto png_drawn = cs.console({"render upload"});
  ASSERT_EQ(png_drawn.status, 0) << png_drawn.err;
  EXPECT_EQ(field_after(png_drawn.out, "crc32 "), obj_crc) << png_drawn.out;

  // With its texture (the model's 64 x 64 checkerboard, sent as its 32 x 32 mip level: the
  // firmware's checkerboard), the cube draws the checkerboard's frame again.
  // `texture FILE FORMAT` in htx console: a format word, and a line with one word too many refused.
  const auto line = cs.console({"texture " + ramp + " rgba4444", "info", "texture " + ramp + " rgba4444 extra"});
  EXPECT_NE(line.status, 0);
  EXPECT_NE(line.out.find("texture ok: 16x64 rgba4444, 7 levels"), std::string::npos) << line.out;
  EXPECT_NE(line.err.find("usage: texture IMAGE.png [rgb565|rgba4444 [SLOT]]"), std::string::npos) << line.err;
  const auto with = cs.console({"upload cube", "render cube", "quit"});
  EXPECT_NE(with.out.find("texture ok: 32x32 rgb565, 6 levels"), std::string::npos) << with.out;
  EXPECT_NE(with.err.find("the scene's 64x64 texture sent as its 32x32 mip level"), std::string::npos) << with.err;
  EXPECT_EQ(render_crc(with.out), checker_crc) << with.out;
  EXPECT_EQ(sim.wait(60s), 0);
}

// Texture slots: `htx upload nearclip` sends its two textures into slots 0 and 1, each beside the
// textures in use (slot 0's at the memory's end, so that the boot checkerboard's blocks, freed
// once slot 0 moved off them, join the free space: place_texture_chain); a third
// 32 x 32 chain does not fit the 340 blocks left and is refused with every texture kept; a new
// texture for slot 1 goes over slot 1's own; a small one fits beside; a slot the console does not
// have is refused before anything is sent. The uploaded scene draws with its meshes' slots.
TEST(SystemConsole, TextureSlotsShareTheTextureMemory) {
  ConsoleSim cs;
  htx::test::Child& sim = cs.sim;
  const std::string& pty = cs.pty;
  ASSERT_FALSE(pty.empty()) << sim.output();
  const auto up = htx::test::run_program({HTX_BIN, "upload", "nearclip", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(up.status, 0) << up.err;
  EXPECT_NE(up.out.find("texture ok: 32x32 rgb565, 6 levels, slot 0 at blocks 682..1023 (342 of 1024 in use)"),
            std::string::npos)
      << up.out;
  EXPECT_NE(up.out.find("texture ok: 32x32 rgb565, 6 levels, slot 1 at blocks 0..341 (684 of 1024 in use)"),
            std::string::npos)
      << up.out;
  const auto two = cs.console({"info", "render upload"});
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_NE(two.out.find("texture 1: 32x32 rgb565 (uploaded)"), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("texture 2: none (its meshes draw with texture 0)"), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("texture memory: 684 of 1024 blocks"), std::string::npos) << two.out;
  const std::string two_crc = field_after(two.out, "crc32 ");
  ASSERT_TRUE(IsCrc32(two_crc)) << two.out;

  const std::string ramp = ::testing::TempDir() + "htx_console_slot_ramp.png";
  write_texture_png(ramp, 32, 32, [](int x, int v) {
    return std::array<uint8_t, 4>{static_cast<uint8_t>(x * 8), static_cast<uint8_t>(v * 8), 90, 255};
  });
  const auto third =
      htx::test::run_program({HTX_BIN, "upload", "--texture", ramp, "--slot", "2", "--port", pty, "--timeout", "60"}, 180s);
  EXPECT_NE(third.status, 0);
  EXPECT_NE(third.err.find("error: not a valid texture (its mip chain does not fit beside the other slots' textures); "
                           "the texture is unchanged"),
            std::string::npos)
      << third.err;
  const auto kept = cs.console({"info", "render upload"});
  ASSERT_EQ(kept.status, 0) << kept.err;
  EXPECT_NE(kept.out.find("texture 2: none"), std::string::npos) << kept.out;
  EXPECT_EQ(field_after(kept.out, "crc32 "), two_crc) << kept.out;

  const auto over =
      htx::test::run_program({HTX_BIN, "upload", "--texture", ramp, "--slot", "1", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(over.status, 0) << over.err;
  EXPECT_NE(over.out.find("slot 1 at blocks 0..341 (684 of 1024 in use)"), std::string::npos) << over.out;
  const auto small = cs.console({"texture " + ramp + " rgba4444 3", "render upload", "render cube"});
  EXPECT_NE(small.status, 0) << "32 x 32 does not fit beside two others\n" << small.out;
  const std::string tiny = ::testing::TempDir() + "htx_console_slot_tiny.png";
  write_texture_png(tiny, 8, 8, [](int x, int) { return std::array<uint8_t, 4>{static_cast<uint8_t>(x * 30), 0, 0, 255}; });
  const auto fits = cs.console({"texture " + tiny + " rgb565 3", "info", "render upload"});
  ASSERT_EQ(fits.status, 0) << fits.err;
  EXPECT_NE(fits.out.find("texture ok: 8x8 rgb565, 4 levels, slot 3 at blocks 342..363 (706 of 1024 in use)"),
            std::string::npos)
      << fits.out;
  EXPECT_NE(fits.out.find("texture 3: 8x8 rgb565 (uploaded)"), std::string::npos) << fits.out;
  const std::string ramp_crc = field_after(fits.out, "crc32 ");
  ASSERT_TRUE(IsCrc32(ramp_crc)) << fits.out;
  EXPECT_NE(ramp_crc, two_crc) << "slot 1's meshes draw with the ramp now";

  const auto no_slot =
      htx::test::run_program({HTX_BIN, "upload", "--texture", tiny, "--slot", "4", "--port", pty}, 60s);
  EXPECT_NE(no_slot.status, 0);
  EXPECT_NE(no_slot.err.find("--slot"), std::string::npos) << no_slot.err;
  {  // the console's own check, typed (htx console takes `texture` as its own command)
    const int fd = htx::test::open_raw_terminal(pty);
    ASSERT_GE(fd, 0) << "cannot open " << pty << " raw";
    const std::string cmd = "texture 2060 12345678 7\r";
    ASSERT_EQ(write(fd, cmd.data(), cmd.size()), static_cast<ssize_t>(cmd.size()));
    std::string got;
    EXPECT_TRUE(htx::test::read_fd_until(fd, got, "htx> ", 60s)) << got;
    EXPECT_NE(got.find("error: texture slot 7 is not one of the console's 0..3; nothing was received"),
              std::string::npos)
        << got;
    close(fd);
  }
  EXPECT_EQ(cs.console({"quit"}).status, 0);
  EXPECT_EQ(sim.wait(60s), 0);
}

// Scenes larger than the vertex cache go in parts: the floor split into meshes of at most 30
// vertices draws exactly the compiled-in floor's frame (the parts keep the whole mesh's transform
// precision, so shared edges meet), and randmesh (7,248 bytes, four meshes) is taken and drawn.
TEST(SystemConsole, MeshesLargerThanTheVertexCacheGoInParts) {
  ConsoleSim cs;
  htx::test::Child& sim = cs.sim;
  const std::string& pty = cs.pty;
  ASSERT_FALSE(pty.empty()) << sim.output();
  const auto compiled = cs.console({"render floor"});
  ASSERT_EQ(compiled.status, 0) << compiled.err;
  const std::string floor_crc = field_after(compiled.out, "crc32 ");
  ASSERT_TRUE(IsCrc32(floor_crc)) << compiled.out;

  const auto up = htx::test::run_program(
      {HTX_BIN, "upload", "floor", "--mesh-vertices", "30", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(up.status, 0) << up.err;
  EXPECT_NE(up.err.find("upload: 1 meshes sent as "), std::string::npos) << up.err;
  EXPECT_NE(up.out.find("128 triangles"), std::string::npos) << up.out;
  const std::string parts = field_after(up.out, "bytes, ");
  ASSERT_TRUE(IsCount(parts)) << up.out;
  EXPECT_GT(std::stoi(parts), 3) << up.out;
  const auto split = cs.console({"render upload"});
  ASSERT_EQ(split.status, 0) << split.err;
  EXPECT_EQ(field_after(split.out, "crc32 "), floor_crc) << split.out;

  const auto rand = htx::test::run_program({HTX_BIN, "upload", "randmesh", "--port", pty, "--timeout", "60"}, 180s);
  ASSERT_EQ(rand.status, 0) << rand.err;
  EXPECT_NE(rand.out.find("upload ok: 7248 bytes, 4 meshes"), std::string::npos) << rand.out;
  const auto drawn = cs.console({"render upload", "quit"});
  EXPECT_NE(drawn.out.find("render upload method auto filter scene triangles"), std::string::npos) << drawn.out;
  EXPECT_EQ(drawn.out.find("error"), std::string::npos) << drawn.out;
  EXPECT_EQ(sim.wait(60s), 0);
}

}  // namespace
