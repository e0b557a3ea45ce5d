// The console firmware on the simulated SoC, driven by htx's own console tools through the
// pseudo-terminal of `htx sim --uart pty`, as a user would drive a board: commands and their
// errors, a render, a frame download equal to the frame the render firmware leaves on the SoC,
// and `quit` ending the simulation with status 0.
#include <gtest/gtest.h>

#include <string>

#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::string field_after(const std::string& text, const std::string& key) {
  const size_t at = text.find(key);
  if (at == std::string::npos) return "";
  const size_t start = at + key.size();
  return text.substr(start, text.find_first_of(" \r\n", start) - start);
}

TEST(SystemConsole, CommandsRenderAndGrabThroughThePseudoTerminal) {
  htx::test::Child sim({HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/console.elf", "--uart", "pty", "--max-cycles",
                        "2000000000"});
  const std::string marker = "htx sim: UART on ";
  ASSERT_TRUE(sim.read_until("\n", 30s)) << sim.output();
  const size_t at = sim.output().find(marker);
  ASSERT_NE(at, std::string::npos) << sim.output();
  const std::string pty = sim.output().substr(at + marker.size(), sim.output().find('\n', at) - at - marker.size());

  const auto console = [&pty](std::vector<std::string> commands) {
    std::vector<std::string> argv = {HTX_BIN, "console", "--port", pty, "--timeout", "60"};
    for (const std::string& c : commands) argv.insert(argv.end(), {"-c", c});
    return htx::test::run_program(argv, 180s);
  };
  const auto r = console({"info", "set method bogus", "set tolerance 1/0", "frobnicate", std::string(120, 'x'),
                          "render nosuch", "stats", "render cube", "stats"});
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("screen 160x120 rgb565"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("method auto; tolerance 1/16 texel"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown method bogus"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: tolerance wants 1/N with N = 1..65536, not 1/0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown command (type help): frobnicate"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: line longer than 96 characters"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: unknown scene nosuch"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error: nothing rendered yet"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("triangles 6 fragments 7082 pixels 7082"), std::string::npos) << r.out;
  const std::string crc = field_after(r.out.substr(r.out.find("render cube method auto")), "crc32 ");
  ASSERT_EQ(crc.size(), 8u) << r.out;

  const std::string png = ::testing::TempDir() + "htx_console_grab.png";
  const auto g = htx::test::run_program({HTX_BIN, "grab", "--port", pty, "--out", png, "--timeout", "60"}, 180s);
  ASSERT_FALSE(g.timed_out);
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_NE(g.out.find("160x120 frame"), std::string::npos) << g.out;
  EXPECT_EQ(field_after(g.out, "crc32 "), crc) << g.out;

  const auto q = console({"quit"});
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

}  // namespace
