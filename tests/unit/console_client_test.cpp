// htx's console client (host_tools/console) against a scripted console on a pseudo-terminal: the
// command exchange, a good frame download, and every way a download can go wrong (a damaged
// packet, a missing one, a checksum that does not match, no frame, silence) ending in a clear error.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "htx/console/console_client.hpp"
#include "htx/console/serial_port.hpp"
#include "htx/fw/console_packet.h"
#include "htx/fw/crc32.h"
#include "htx/fw/rle16.h"

namespace {

using namespace std::chrono_literals;
using htx::console::ConsoleClient;
using htx::console::SerialPort;

// The console's behaviour; the upload modes: kNakOnce asks for the first packet again, kRefuse
// refuses the upload, kNeverAck takes nothing, kSpuriousNak answers the first packet with a Nak it
// was not asked for and then its Ack (as a CR LF line end's stray LF did: every answer after it is
// one packet late), kLastAckDamaged damages the last packet's Ack (its verdict follows as text),
// kGivesUp stops after the first packet with its own timeout's error. Two devices that are not a
// console: kTrickle sends a byte every 50 ms and never a prompt (as a port at another baud rate
// shows a stream of bytes), kChatty greets with a prompt and then prints a line every 50 ms, and
// kPromptOnly answers every line with a prompt alone (no echo, no answer), kEcho sends back what
// it gets (a loop-back cable, or a terminal program at the other end). kBusyGrab is a console
// still sending a frame a grab left (a packet every 50 ms for 2.5 s) before it reads its input.
enum class GrabMode {
  kGood,
  kGap,
  kDamaged,
  kBadCrc,
  kNoFrame,
  kSilent,
  kNakOnce,
  kRefuse,
  kNeverAck,
  kSpuriousNak,
  kLastAckDamaged,
  kGivesUp,
  kTrickle,
  kChatty,
  kPromptOnly,
  kEcho,
  kBusyGrab
};

// The console's side: answers each line it reads from the master end of a pty.
class FakeConsole {
 public:
  explicit FakeConsole(GrabMode mode) : mode_(mode) {
    if (::openpty(&master_, &slave_, nullptr, nullptr, nullptr) != 0) throw std::runtime_error("openpty");
    path_ = ::ptsname(master_);
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeConsole() {
    stop_ = true;
    thread_.join();
    ::close(master_);
    ::close(slave_);
  }
  const std::string& path() const { return path_; }
  // The frame it sends: 3 x 2 pixels.
  static std::vector<uint16_t> pixels() { return {0x1234, 0x1234, 0x1234, 0xF800, 0x07E0, 0x001F}; }

 private:
  void put(const std::string& s) { (void)!::write(master_, s.data(), s.size()); }
  void put(const std::vector<uint8_t>& b) { (void)!::write(master_, b.data(), b.size()); }
  void packet(uint8_t type, uint8_t seq, const std::vector<uint8_t>& payload, bool damage = false) {
    std::vector<uint8_t> line(htx::fw::kPacketMaxLine);
    line.resize(htx::fw::packet_encode(type, seq, payload.data(), payload.size(), line.data()));
    if (damage) line[3] ^= 0x10;
    put(line);
  }
  void send_frame() {
    const std::vector<uint16_t> px = pixels();
    std::vector<uint8_t> raw;
    for (uint16_t p : px) raw.insert(raw.end(), {static_cast<uint8_t>(p), static_cast<uint8_t>(p >> 8)});
    std::vector<uint8_t> info(10);
    htx::fw::put_le16(info.data(), 3);
    htx::fw::put_le16(info.data() + 2, 2);
    info[4] = 0;
    info[5] = 1;
    htx::fw::put_le32(info.data() + 6, htx::fw::crc32(raw.data(), raw.size()) ^ (mode_ == GrabMode::kBadCrc ? 1u : 0u));
    std::vector<uint8_t> code(htx::fw::rle16_max_size(px.size()));
    code.resize(htx::fw::rle16_encode(px.data(), px.size(), code.data()));
    const std::vector<uint8_t> first(code.begin(), code.begin() + 3), second(code.begin() + 3, code.end());
    packet(htx::fw::kPacketFrameInfo, 7, info);
    packet(htx::fw::kPacketFrameData, 8, first, mode_ == GrabMode::kDamaged);
    packet(htx::fw::kPacketFrameData, mode_ == GrabMode::kGap ? 10 : 9, second);
    std::vector<uint8_t> end(8);
    htx::fw::put_le32(end.data(), 2);
    htx::fw::put_le32(end.data() + 4, static_cast<uint32_t>(code.size()));
    packet(htx::fw::kPacketFrameEnd, mode_ == GrabMode::kGap ? 11 : 10, end);
  }
  void answer(const std::string& line) {
    if (line.empty()) return put("\r\nhtx> ");
    put(line + "\r\n");
    if (line == "info") return put("line one\r\nline two\r\nhtx> ");
    if (line == "spin") return spin();
    if (line == "baud 1000000") return put("ok 1000000 baud\r\nhtx> ");
    if (line.rfind("baud ", 0) == 0) return put("error: " + line.substr(5) + " baud is not one this UART makes\r\nhtx> ");
    if (line != "grab") return put("error: unknown command (type help): " + line + "\r\nhtx> ");
    if (mode_ == GrabMode::kSilent) return;
    if (mode_ == GrabMode::kNoFrame) return put("error: no framebuffer\r\nhtx> ");
    send_frame();
    put("htx> ");
  }
  // As the console's spin: a line a frame (20 ms apart), 20 frames, or fewer when a key comes; the
  // key is left for the line reader, which then reads it as the start of the next line.
  void spin() {
    int frames = 0;
    bool stopped = false;
    while (frames < 20 && !stopped) {
      put("frame " + std::to_string(++frames) + "\r\n");
      pollfd p{master_, POLLIN, 0};
      stopped = ::poll(&p, 1, 20) > 0;
    }
    put("spin frames " + std::to_string(frames) + (stopped ? " (stopped)" : "") + "\r\nhtx> ");
  }
  void reply(uint8_t type, uint8_t seq, bool damage = false) { packet(type, 0, {seq}, damage); }
  // A packet of an upload arrived: acknowledge it (or not, as the mode says).
  void upload_packet(const htx::fw::Packet& p) {
    if (p.type == htx::fw::kPacketAbort) {
      uploading_ = false;
      return put("error: the host abandoned the upload; the scene is unchanged\r\nhtx> ");
    }
    ++packets_in_;
    if (mode_ == GrabMode::kNeverAck || (mode_ == GrabMode::kNakOnce && naks_ == 0)) {
      ++naks_;
      return reply(htx::fw::kPacketNak, p.seq);
    }
    if (p.seq != static_cast<uint8_t>(upload_packets_)) return reply(htx::fw::kPacketAck, p.seq);  // a repeat
    if (mode_ == GrabMode::kGivesUp && upload_packets_ == 1) {
      uploading_ = false;
      return put("error: upload timed out after " + std::to_string(received_) + " of " +
                 std::to_string(upload_size_) + " bytes; the scene is unchanged\r\nhtx> ");
    }
    if (mode_ == GrabMode::kSpuriousNak && upload_packets_ == 0 && naks_ == 0) {
      ++naks_;
      reply(htx::fw::kPacketNak, 0);
    }
    received_ += p.len;
    ++upload_packets_;
    reply(htx::fw::kPacketAck, p.seq, mode_ == GrabMode::kLastAckDamaged && received_ == upload_size_);
    if (received_ == upload_size_) {
      uploading_ = false;
      put("upload ok: " + std::to_string(received_) + " bytes\r\nhtx> ");
    }
  }
  void serve() {
    if (mode_ == GrabMode::kTrickle || mode_ == GrabMode::kChatty) return stream();
    if (mode_ == GrabMode::kBusyGrab) {
      for (int i = 0; i < 50; ++i) {
        packet(htx::fw::kPacketFrameData, static_cast<uint8_t>(i), std::vector<uint8_t>(16, static_cast<uint8_t>(i)));
        std::this_thread::sleep_for(50ms);
      }
    }
    if (mode_ != GrabMode::kEcho) put("hypertex console. Type help.\r\nhtx> ");
    std::string line;
    htx::fw::PacketDecoder decoder;
    while (!stop_) {
      pollfd p{master_, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      char c;
      if (::read(master_, &c, 1) != 1) continue;
      if (mode_ == GrabMode::kEcho) {
        put(std::string(1, c));
      } else if (uploading_) {
        htx::fw::Packet packet;
        if (htx::fw::packet_feed(&decoder, static_cast<uint8_t>(c), &packet) == htx::fw::kPacketReady)
          upload_packet(packet);
      } else if (c == '\r' && mode_ == GrabMode::kPromptOnly) {
        put("htx> ");
        line.clear();
      } else if (c == '\r') {
        if (line.rfind("upload ", 0) == 0 || line.rfind("texture ", 0) == 0) {
          put(line + "\r\n");
          upload_line_ = line;
          upload_size_ = std::stoul(line.substr(line.find(' ') + 1));
          received_ = 0;
          upload_packets_ = 0;
          if (mode_ == GrabMode::kRefuse) {
            put("error: a scene of " + std::to_string(upload_size_) + " bytes does not fit the store (1..3072)\r\nhtx> ");
          } else {
            put("ready\r\n");
            uploading_ = true;
          }
        } else {
          answer(line);
        }
        line.clear();
      } else {
        line += c;
      }
    }
  }
  void stream() {
    if (mode_ == GrabMode::kChatty) put("hypertex console. Type help.\r\nhtx> ");
    while (!stop_) {
      put(mode_ == GrabMode::kChatty ? "noise\r\n" : "~");
      char drop[64];
      pollfd p{master_, POLLIN, 0};
      if (::poll(&p, 1, 50) > 0) (void)!::read(master_, drop, sizeof drop);
    }
  }

 public:
  int naks() const { return naks_; }
  size_t upload_packets() const { return upload_packets_; }
  size_t packets_in() const { return packets_in_; }  // every data packet that arrived, repeats too
  std::string upload_line() const { return upload_line_; }

 private:
  bool uploading_ = false;
  size_t upload_size_ = 0, received_ = 0, upload_packets_ = 0, packets_in_ = 0;
  std::string upload_line_;
  int naks_ = 0;

  GrabMode mode_;
  int master_ = -1, slave_ = -1;
  std::string path_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// converse: each line of the answer reaches the caller as it arrives, without the echo and the
// prompt; a stop sends one key, which ends a spin after its frame and whose empty line's prompt is
// taken, so the next command gets its own answer; without a stop the spin runs to its end.
TEST(ConsoleClient, ConverseShowsEachLineAsItComesAndStopsWithOneKey) {
  FakeConsole fake(GrabMode::kGood);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 1500ms);
  client.sync();
  std::vector<std::string> shown;
  int asked = 0;
  client.converse("spin", [&shown](const std::string& text) { shown.push_back(text); },
                  [&asked] { return ++asked == 3; });
  ASSERT_GE(shown.size(), 3u);
  EXPECT_EQ(shown.front(), "frame 1\n");
  EXPECT_NE(shown.back().find("(stopped)"), std::string::npos) << shown.back();
  EXPECT_LT(shown.size(), 21u) << "the spin ran to its end";
  EXPECT_EQ(client.command("info"), "line one\nline two\n");

  shown.clear();
  client.converse("spin", [&shown](const std::string& text) { shown.push_back(text); });
  ASSERT_EQ(shown.size(), 21u);
  EXPECT_EQ(shown.back(), "spin frames 20\n");
  EXPECT_EQ(client.command("info"), "line one\nline two\n");
  EXPECT_THROW(client.converse("two\nlines", [](const std::string&) {}), std::invalid_argument);
}

std::string grab_error(GrabMode mode) {
  FakeConsole fake(mode);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 1500ms);
  client.sync();
  try {
    client.grab();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(ConsoleClient, CommandOutputWithoutEchoOrPrompt) {
  FakeConsole fake(GrabMode::kGood);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 2s);
  client.sync();
  EXPECT_EQ(client.command("info"), "line one\nline two\n");
  EXPECT_EQ(client.command("bogus"), "error: unknown command (type help): bogus\n");
  EXPECT_THROW(client.command("two\nlines"), std::invalid_argument);
}

TEST(ConsoleClient, GrabDecodesAndChecksTheFrame) {
  FakeConsole fake(GrabMode::kGood);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 2s);
  client.sync();
  size_t progress = 0;
  const htx::console::GrabbedFrame f = client.grab([&progress](size_t bytes) { progress = bytes; });
  EXPECT_EQ(f.width, 3);
  EXPECT_EQ(f.height, 2);
  EXPECT_EQ(f.pixels, FakeConsole::pixels());
  EXPECT_EQ(f.data_packets, 2u);
  EXPECT_EQ(progress, f.coded_bytes);
  // The exchange is back at a prompt: the next command works.
  EXPECT_EQ(client.command("info"), "line one\nline two\n");
}

TEST(ConsoleClient, GrabFailuresSayWhatWentWrong) {
  EXPECT_NE(grab_error(GrabMode::kDamaged).find("damaged"), std::string::npos) << grab_error(GrabMode::kDamaged);
  EXPECT_NE(grab_error(GrabMode::kGap).find("packet 9 is missing"), std::string::npos);
  EXPECT_NE(grab_error(GrabMode::kBadCrc).find("CRC-32 does not match"), std::string::npos);
  EXPECT_NE(grab_error(GrabMode::kNoFrame).find("sent no frame: error: no framebuffer"), std::string::npos);
  EXPECT_NE(grab_error(GrabMode::kSilent).find("said nothing for"), std::string::npos);
  // A device that only prompts: the message says what came instead of leaving it blank.
  EXPECT_EQ(grab_error(GrabMode::kPromptOnly),
            "grab: the console sent no frame: only a prompt, without the command's echo (is this the console?)");
}

TEST(ConsoleClient, UploadResendsWhatWasNotTakenAndReportsTheVerdict) {
  std::vector<uint8_t> scene(600);
  for (size_t i = 0; i < scene.size(); ++i) scene[i] = static_cast<uint8_t>(i * 7);
  {
    FakeConsole fake(GrabMode::kNakOnce);
    SerialPort port(fake.path(), 115200);
    ConsoleClient client(port, 2s);
    client.sync();
    EXPECT_EQ(client.upload(scene), "upload ok: 600 bytes\n");
    EXPECT_EQ(fake.naks(), 1);
    EXPECT_EQ(fake.upload_packets(), 3u);  // 240 + 240 + 120, the first sent twice
    EXPECT_EQ(client.resent_packets(), 1u);
    EXPECT_EQ(client.command("info"), "line one\nline two\n");
  }
  const auto upload_error = [&scene](GrabMode mode) -> std::string {
    FakeConsole fake(mode);
    SerialPort port(fake.path(), 115200);
    ConsoleClient client(port, 2s);
    client.sync();
    try {
      client.upload(scene);
    } catch (const std::invalid_argument& e) {  // the console's refusal: the line is at a prompt
      EXPECT_EQ(client.command("info"), "line one\nline two\n");
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(upload_error(GrabMode::kRefuse),
            "upload: the console refused: error: a scene of 600 bytes does not fit the store (1..3072)");
  EXPECT_EQ(upload_error(GrabMode::kNeverAck),
            "upload: packet 0 was not taken after 8 tries; the console's scene is unchanged");
  // The console's own error ends the transfer in its words (waiting for an answer, the client used
  // to wait out its timeout and report silence, a std::runtime_error).
  EXPECT_EQ(upload_error(GrabMode::kGivesUp),
            "upload: error: upload timed out after 240 of 600 bytes; the scene is unchanged\n");
}

// Answers out of step or lost: a Nak the host did not cause is answered by sending the packet
// again, and the Ack of that repeat, which comes late, is not taken for a refusal of the next
// packet (each later packet would otherwise go twice); a damaged Ack of the last packet is not
// answered by sending it again (the console has finished and would read the copy as a typed line):
// its verdict, which follows as text, ends the upload.
TEST(ConsoleClient, UploadAnswersOutOfStepOrLostSendNothingTwice) {
  std::vector<uint8_t> scene(600);
  for (size_t i = 0; i < scene.size(); ++i) scene[i] = static_cast<uint8_t>(i * 3);
  {
    FakeConsole fake(GrabMode::kSpuriousNak);
    SerialPort port(fake.path(), 115200);
    ConsoleClient client(port, 2s);
    client.sync();
    EXPECT_EQ(client.upload(scene), "upload ok: 600 bytes\n");
    EXPECT_EQ(fake.upload_packets(), 3u);
    EXPECT_EQ(fake.packets_in(), 4u);  // the first twice, as its Nak asked
    EXPECT_EQ(client.resent_packets(), 1u);
    EXPECT_EQ(client.command("info"), "line one\nline two\n");
  }
  FakeConsole fake(GrabMode::kLastAckDamaged);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 2s);
  client.sync();
  EXPECT_EQ(client.upload(scene), "upload ok: 600 bytes\n");
  EXPECT_EQ(fake.packets_in(), 3u);
  EXPECT_EQ(client.resent_packets(), 0u);
  EXPECT_EQ(client.command("info"), "line one\nline two\n");
}

// A texture goes the same way, announced as `texture SIZE CRC32 [SLOT]` (zlib's CRC-32 of its bytes).
TEST(ConsoleClient, TextureUploadIsAnnouncedAsTexture) {
  const std::vector<uint8_t> texture = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};  // CRC-32 cbf43926
  {
    FakeConsole fake(GrabMode::kGood);
    SerialPort port(fake.path(), 115200);
    ConsoleClient client(port, 2s);
    client.sync();
    EXPECT_EQ(client.upload(texture, {}, ConsoleClient::Payload::kTexture), "upload ok: 9 bytes\n");
    EXPECT_EQ(fake.upload_line(), "texture 9 cbf43926");
    EXPECT_EQ(client.upload(texture), "upload ok: 9 bytes\n");
    EXPECT_EQ(fake.upload_line(), "upload 9 cbf43926");
    // Another slot is named; slot 0 is not (a console from before the slots takes it so).
    EXPECT_EQ(client.upload(texture, {}, ConsoleClient::Payload::kTexture, 2), "upload ok: 9 bytes\n");
    EXPECT_EQ(fake.upload_line(), "texture 9 cbf43926 2");
  }
  FakeConsole fake(GrabMode::kNeverAck);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 2s);
  client.sync();
  try {
    client.upload(texture, {}, ConsoleClient::Payload::kTexture);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "upload: packet 0 was not taken after 8 tries; the console's texture is unchanged");
  }
  EXPECT_EQ(client.resent_packets(), 7u);
}

// The simulation ends (its side of the pseudo-terminal closes) while htx waits: an error at once,
// not a wait for the timeout.
TEST(ConsoleClient, AClosedOtherEndIsAnErrorNotAHang) {
  int master = -1, slave = -1;
  ASSERT_EQ(::openpty(&master, &slave, nullptr, nullptr, nullptr), 0);
  const std::string path = ::ptsname(master);
  SerialPort port(path, 115200);
  ::close(slave);
  ::close(master);
  uint8_t buf[16];
  const auto t0 = std::chrono::steady_clock::now();
  try {
    port.read_some(buf, sizeof buf, 10s);
    ADD_FAILURE() << "read_some returned";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("closed at the other end"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 2s);
}

// `baud N`: the port takes the new rate once the console said `ok`, and the exchange goes on at
// its prompt; a refusal is the console's error line, and the port keeps its rate.
TEST(ConsoleClient, BaudSwitchesThePortAfterTheConsolesOk) {
  FakeConsole fake(GrabMode::kGood);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 2s);
  client.sync();
  const auto speed = [&fake] {
    const int fd = ::open(fake.path().c_str(), O_RDONLY | O_NOCTTY);
    termios t{};
    ::tcgetattr(fd, &t);
    ::close(fd);
    return ::cfgetospeed(&t);
  };
  try {
    client.set_baud(3000000);
    ADD_FAILURE() << "a refused rate was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "error: 3000000 baud is not one this UART makes");
  }
  EXPECT_EQ(speed(), static_cast<speed_t>(B115200));
  // A rate the port cannot take is refused before the console is asked (it would switch alone):
  // nothing goes to it, so the next command's answer is its own.
  try {
    client.set_baud(5000000);
    ADD_FAILURE() << "a rate the port cannot take was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("baud 5000000: want 9600, ", 0), 0u) << e.what();
  }
  EXPECT_EQ(client.command("info"), "line one\nline two\n");
  EXPECT_EQ(speed(), static_cast<speed_t>(B115200));
  client.set_baud(1000000);
  EXPECT_EQ(speed(), static_cast<speed_t>(B1000000));
  EXPECT_EQ(client.command("info"), "line one\nline two\n");
  EXPECT_THROW(port.set_baud(12345), std::invalid_argument);
}

// A device that keeps sending but is not a console (no prompt, or no pause after it) is an error
// within twice the timeout: `--timeout` measures silence, which such a stream never gives.
TEST(ConsoleClient, AStreamWithoutAConsoleIsAnErrorNotAHang) {
  for (GrabMode mode : {GrabMode::kTrickle, GrabMode::kChatty}) {
    FakeConsole fake(mode);
    SerialPort port(fake.path(), 115200);
    ConsoleClient client(port, 1s);
    const auto t0 = std::chrono::steady_clock::now();
    try {
      client.sync();
      ADD_FAILURE() << "sync returned";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("without a console prompt and a pause after it"), std::string::npos)
          << e.what();
    }
    const auto took = std::chrono::steady_clock::now() - t0;
    EXPECT_GE(took, 2s);
    EXPECT_LT(took, 4s);
  }
}

// A console sending the rest of a frame when htx attaches (a grab interrupted) is waited for past
// twice the timeout, since each whole packet shows a console at work; then the exchange works.
TEST(ConsoleClient, AFrameStillComingIsWaitedFor) {
  FakeConsole fake(GrabMode::kBusyGrab);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 500ms);
  const auto t0 = std::chrono::steady_clock::now();
  client.sync();
  EXPECT_GE(std::chrono::steady_clock::now() - t0, 2s);
  EXPECT_EQ(client.command("info"), "line one\nline two\n");
}

// A device that only echoes: its bytes are quoted in the error, which used to blame silence.
TEST(ConsoleClient, AnEchoIsNotAConsole) {
  FakeConsole fake(GrabMode::kEcho);
  SerialPort port(fake.path(), 115200);
  ConsoleClient client(port, 1s);
  try {
    client.sync();
    ADD_FAILURE() << "sync returned";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("no console prompt: the port sent ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("(\"\\x0d\\x00"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("then nothing for 1 s (an echo of what htx sent?"), std::string::npos)
        << e.what();
  }
}

TEST(ConsoleClient, RefusesAPathThatIsNotATerminal) {
  EXPECT_THROW(SerialPort("/nonexistent/tty", 115200), std::runtime_error);
  EXPECT_THROW(SerialPort("/dev/null", 115200), std::runtime_error);
  FakeConsole fake(GrabMode::kGood);
  EXPECT_THROW(SerialPort(fake.path(), 12345), std::invalid_argument);
}

}  // namespace
