// The echo firmware on the simulated SoC, reached the way a person would: `htx sim --uart pty`
// prints a pseudo-terminal path, a serial program opens it in raw mode, reads the greeting, types
// and gets its characters echoed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

TEST(SystemEcho, GreetsAndEchoesThroughPseudoTerminal) {
  htx::test::Child sim({HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/echo.elf", "--uart", "pty",
                        "--max-cycles", "200000000"});
  const std::string marker = "htx sim: UART on ";
  ASSERT_TRUE(sim.read_until("\n", 30s)) << "no pty path printed; got: " << sim.output();
  const size_t at = sim.output().find(marker);
  ASSERT_NE(at, std::string::npos) << sim.output();
  const std::string path = sim.output().substr(at + marker.size(),
                                               sim.output().find('\n', at) - at - marker.size());
  ASSERT_EQ(path.rfind("/dev/", 0), 0u) << path;

  const int fd = htx::test::open_raw_terminal(path);
  ASSERT_GE(fd, 0) << "cannot open " << path << " raw";

  std::string got;
  ASSERT_TRUE(htx::test::read_fd_until(fd, got, "Ctrl-D ends.\r\n", 30s)) << "greeting: " << got;
  EXPECT_NE(got.find("hypertex echo"), std::string::npos) << got;

  const std::string typed = "Hello, pty! 0123\r";
  ASSERT_EQ(write(fd, typed.data(), typed.size()), static_cast<ssize_t>(typed.size()));
  std::string echo;
  ASSERT_TRUE(htx::test::read_fd_until(fd, echo, "\r\n", 30s)) << "echo so far: " << echo;
  EXPECT_EQ(echo, "Hello, pty! 0123\r\n");

  const char ctrl_d = 0x04;
  ASSERT_EQ(write(fd, &ctrl_d, 1), 1);
  std::string bye;
  EXPECT_TRUE(htx::test::read_fd_until(fd, bye, "bye\r\n", 30s)) << bye;
  close(fd);
  EXPECT_EQ(sim.wait(30s), 0) << "htx sim should end with the firmware's status 0";
}

}  // namespace
