// The console firmware against random command lines (label `fuzz`): a fixed-seed script of
// commands, arguments and junk (unknown words, numbers out of range, stray `over` and `hold`, lines
// too long, control characters, backspaces), typed into `htx sim --uart stdio`. Every line gets a
// prompt back (exactly one per line the console reads, counted from the script by the console's
// line-end rules), the run never hangs or traps, and afterwards, with the settings put back, the cube
// draws the frame it draws at boot. Commands that wait for binary data or change the line (upload,
// texture, grab, baud) and quit are left out of the junk; their own tests cover their bad input.
// With HTX_KEEP_FUZZ set, the script and the console's output stay in the test's temporary folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;

std::string pick(std::mt19937& rng, const std::vector<std::string>& words) { return words[rng() % words.size()]; }

// One random console line (without its line end).
std::string random_line(std::mt19937& rng) {
  static const std::vector<std::string> kNumbers = {"0", "1", "16", "65536", "65537", "-1", "4294967296",
                                                    "99999999999999999999", "0x10", "1e3", "", "7"};
  switch (rng() % 12) {
    case 0:
      return "set method " + pick(rng, {"auto", "affine", "subdiv0", "subdiv2", "subdiv64", "subdiv65", "subdiv",
                                        "recip_lut", "recip_nr", "divfree", "quadratic", "AUTO", ""});
    case 1:
      return "set tolerance " + pick(rng, {"1/", "/16", "1/0", "2/3", "1/x"}) + pick(rng, kNumbers);
    case 2:
      return "set filter " + pick(rng, {"nearest", "bilinear", "trilinear", "scene", "cubic", "", "nearest nearest"});
    case 3:
      // Mostly errors (a scene not there, bad words) so that few lines draw: a draw is 1-2 M clocks.
      return "render " + pick(rng, {"nosuch", "upload", "", "cube cube", "cube over over", "cube hold hold",
                                    "floor sideways", rng() % 4 == 0 ? "cube hold" : "x", "cube over hold"});
    case 4:
      return pick(rng, {"info", "help", "scenes", "stats", "video on", "video off", "video maybe", "info now"});
    case 5:
      return "spin " + pick(rng, {"nosuch", "cube 0", "cube 3601", "cube x", "cube 1 crc crc", "floor -1"});
    case 6:
      return "set " + pick(rng, {"", "method", "speed 3", "tolerance", "filter"});
    case 7: {  // printable junk, sometimes past the 96-character line
      std::string s(rng() % 130, ' ');
      for (char& c : s) c = static_cast<char>(' ' + rng() % 95);
      return s;
    }
    case 8: {  // a word typed with mistakes and erased (backspace and DEL)
      return std::string("inf") + static_cast<char>(0x7F) + "fo" + static_cast<char>(0x08) + "o";
    }
    case 9:  // abandoned with Ctrl-C, then a command on the next line
      return std::string("render cube") + static_cast<char>(0x03) + "\ninfo";
    case 10:
      return pick(rng, {"", " ", "\t", "   info   ", "INFO", "render\tcube"});
    default:
      return pick(rng, {"upload", "texture", "baud", "upload x y", "texture 1 2 3 4", "baud fast"}) ;
  }
}

TEST(ConsoleFuzz, RandomLinesGetAnAnswerAndLeaveTheConsoleWorking) {
  std::mt19937 rng(20261206);
  const std::string script = ::testing::TempDir() + "htx_console_fuzz_" + std::to_string(getpid()) + ".txt";
  // At 1 Mbaud the run's characters cost a ninth of the clocks they do at 115,200.
  std::string text = "baud 1000000\nrender cube\n";
  for (int i = 0; i < 400; ++i) text += random_line(rng) + "\r";
  text += "\nset method auto\nset tolerance 1/16\nset filter scene\nvideo on\nrender cube\nquit\n";
  std::ofstream(script, std::ios::binary) << text;
  // The lines the console reads from it (firmware/app/console/line_reader.cpp): each CR ends one,
  // each LF not right after a CR, and each Ctrl-C (which abandons its line). A zero byte would
  // start a packet frame, whose bytes are not text: the script has none.
  ASSERT_EQ(text.find('\0'), std::string::npos);
  size_t lines = 0;
  bool after_cr = false;
  for (const char c : text) {
    lines += c == '\r' || c == '\x03' || (c == '\n' && !after_cr);
    after_cr = c == '\r';
  }
  const auto r = htx::test::run_program(
      {"/bin/sh", "-c",
       std::string(HTX_BIN) + " sim --elf " HTX_FIRMWARE_DIR "/console.elf --uart stdio --max-cycles 600000000 < " +
           script},
      300s);
  if (!std::getenv("HTX_KEEP_FUZZ")) std::filesystem::remove(script);
  else std::ofstream(script + ".out") << r.out << r.err;
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.err << r.out.substr(r.out.size() > 4000 ? r.out.size() - 4000 : 0);
  EXPECT_NE(r.err.find("exit code 0"), std::string::npos) << r.err;
  EXPECT_NE(r.out.rfind("bye"), std::string::npos);
  // The first and the last render of the cube, at the same settings, draw the same frame.
  const std::regex cube(R"(render cube method auto filter scene [^\r\n]* crc32 ([0-9a-f]{8}))");
  std::vector<std::string> crcs;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), cube); it != std::sregex_iterator(); ++it)
    crcs.push_back((*it)[1]);
  ASSERT_GE(crcs.size(), 2u) << r.out;
  EXPECT_EQ(crcs.front(), crcs.back());
  // A prompt for every line (the baud, the first render, the junk, the settings, the last render),
  // no more and no fewer: the one at boot, and one after each line's answer but `quit`'s.
  size_t prompts = 0;
  for (size_t at = r.out.find("htx> "); at != std::string::npos; at = r.out.find("htx> ", at + 1)) ++prompts;
  EXPECT_EQ(prompts, 1 + (lines - 1)) << r.out.substr(r.out.size() > 4000 ? r.out.size() - 4000 : 0);
  EXPECT_EQ(r.out.find("trap"), std::string::npos);
}

}  // namespace
