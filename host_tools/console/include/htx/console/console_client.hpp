// The host side of the console's exchange (docs/console.md): command lines out, their output back
// up to the next prompt; `grab`'s packets checked and decoded into a frame.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "htx/console/serial_port.hpp"
#include "htx/fw/console_packet.h"

namespace htx::console {

inline constexpr const char* kPrompt = "htx> ";

struct GrabbedFrame {
  int width = 0, height = 0;
  std::vector<uint16_t> pixels;  // RGB565, row-major
  uint32_t crc32 = 0;            // the console's checksum of the pixels (checked against them)
  size_t coded_bytes = 0, data_packets = 0;
};

class ConsoleClient {
 public:
  // `timeout`: the longest silence to wait through (a render in the simulator is seconds of it).
  ConsoleClient(SerialPort& port, std::chrono::milliseconds timeout);

  // Brings the exchange to a fresh prompt: sends a line break and reads until a prompt followed by
  // a moment of silence, so a greeting or prompt printed before we attached is consumed. A port
  // that keeps sending without giving both within twice the timeout (a device that is not the
  // console, or one at another baud rate, sends a stream of bytes) is a std::runtime_error; whole
  // packets in the stream (the rest of a frame an interrupted grab left) each extend that by the
  // timeout.
  void sync();
  // Sends one line and returns what the console printed for it, without the echoed line and the
  // prompt, with CR LF as LF. Throws std::runtime_error on a timeout.
  std::string command(const std::string& line);
  // command() for a person watching: what the console prints goes to `show` as its lines arrive
  // (a `spin` shows each frame's line as it is drawn), and `stop`, when given, is asked every
  // kStopPoll while the console works; the first time it says yes, one carriage return goes to
  // the console, which stops a running `spin` after its frame (any other command just ends first)
  // and then reads it as an empty command line, whose echo and prompt are taken here unshown. One
  // byte only: the console's receive FIFO holds 16, and a busy console does not read it.
  void converse(const std::string& line, const std::function<void(const std::string&)>& show,
                const std::function<bool()>& stop = {});
  static constexpr std::chrono::milliseconds kStopPoll{50};
  // Sends `grab` and receives the frame. Throws std::runtime_error with the reason on any protocol
  // error (a bad packet, a gap in the sequence, a checksum or size that does not match).
  GrabbedFrame grab(const std::function<void(size_t coded_bytes)>& progress = {});
  // What an upload carries: a packed scene (`upload SIZE CRC32`) or a packed texture (`texture SIZE
  // CRC32 [SLOT]`); both then go as the same packets.
  enum class Payload { kScene, kTexture };
  // Sends a packed scene or texture (the command, then packets, each resent until acknowledged, at
  // most kUploadTries times) and returns the console's verdict line. A texture goes into texture
  // slot `slot` (the slot is named only when not 0, as consoles before texture slots took it).
  // Throws std::invalid_argument with the console's words when it refuses the upload, rejects what
  // arrived, or ends the transfer itself (its own timeout), and when a packet is not taken after
  // kUploadTries tries (the upload is then abandoned): the console's scene or textures are
  // unchanged and the line is at a prompt. Throws std::runtime_error when the line itself fails
  // (silence past the timeout, the port closed).
  std::string upload(const std::vector<uint8_t>& bytes, const std::function<void(size_t sent)>& progress = {},
                     Payload payload = Payload::kScene, unsigned slot = 0);
  static constexpr int kUploadTries = 8;
  // Packets sent again since this client began (a Nak, a damaged answer or none): a line too fast
  // for the console's receive loop shows here first.
  size_t resent_packets() const { return resent_; }
  // `baud N`: the console answers `ok` at the old rate and switches; the port follows, and the
  // prompt then comes at the new rate. Throws std::invalid_argument with the console's error line
  // when it refuses N (the line stays as it was), std::runtime_error when the port cannot take N.
  void set_baud(unsigned baud);

 private:
  uint8_t next_byte();
  // The next byte if one comes within `wait` (false: none came; nothing is thrown).
  bool next_byte_within(std::chrono::milliseconds wait, uint8_t* byte);
  std::string timeout_seconds() const;  // the timeout as the error messages give it ("2", "0.5")
  [[noreturn]] void silence() const;
  // sync's bound on bytes that keep coming without a prompt: a deadline, which each whole packet
  // moves on by the timeout (a console sending the rest of a frame a grab left is a console), and
  // the decoder that finds the packets.
  struct StreamBound {
    std::chrono::steady_clock::time_point start, deadline;
    fw::PacketDecoder decoder{};
    size_t bytes = 0;
    void feed(uint8_t byte, std::chrono::milliseconds extend);
  };
  // Reads into *text until it ends with a prompt; false when `wait` passes in silence first. With
  // `bound`, bytes still coming past its deadline are a std::runtime_error.
  bool prompt_within(std::chrono::milliseconds wait, std::string* text, StreamBound* bound = nullptr);
  [[noreturn]] void no_prompt_in_stream(const StreamBound& bound) const;
  // Bytes came but no prompt, then silence: an error quoting the first of them.
  [[noreturn]] void no_prompt_after(const std::string& seen) const;
  std::string read_until_prompt();
  // Reads text until it ends with `needle` (true) or with a prompt (false: the text without it).
  bool read_text_until(const std::string& needle, std::string* text);
  // Feeds bytes to the packet decoder until a frame ends: a packet, or the reason it is not one.
  fw::PacketStatus next_packet(fw::Packet* p);
  // What came while an upload waited for an answer: a packet, a damaged one, or the console's
  // prompt after a line of text (`text`, without the prompt): it ended the transfer itself.
  enum class Answer { kPacket, kDamaged, kConsolePrompt };
  Answer next_answer(fw::Packet* p, std::string* text);
  void send_packet(uint8_t type, uint8_t seq, const uint8_t* data, size_t len);

  SerialPort& port_;
  std::chrono::milliseconds timeout_;
  std::vector<uint8_t> buf_;
  size_t pos_ = 0;
  fw::PacketDecoder decoder_;
  size_t resent_ = 0;
};

}  // namespace htx::console
