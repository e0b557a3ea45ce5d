#include "htx/console/console_client.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "htx/fw/console_packet.h"
#include "htx/fw/crc32.h"
#include "htx/fw/rle16.h"

namespace htx::console {

namespace {

constexpr auto kSettle = std::chrono::milliseconds(300);
constexpr auto kAbortAfter = std::chrono::milliseconds(1000);  // sync's silence before an Abort
constexpr size_t kMaxText = 1 << 20;  // no answer of the console is near this

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string unix_lines(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != '\r') out += c;
  return out;
}

// Drops the echoed command line (everything up to the first line break).
std::string without_echo(const std::string& s) {
  const size_t nl = s.find('\n');
  return nl == std::string::npos ? std::string() : s.substr(nl + 1);
}

// The console's answer to a command, for an error message: its text without the echoed line, or
// what was there when it said nothing else (a device that only prompts is not the console).
std::string answer_of(const std::string& text) {
  std::string answer = unix_lines(without_echo(text));
  while (!answer.empty() && (answer.back() == '\n' || answer.back() == ' ')) answer.pop_back();
  if (!answer.empty()) return answer;
  return text.find('\n') == std::string::npos ? "only a prompt, without the command's echo (is this the console?)"
                                               : "nothing but the command's echo";
}

const char* status_name(fw::PacketStatus s) {
  switch (s) {
    case fw::kPacketBadCobs: return "not COBS";
    case fw::kPacketTooLong: return "too long";
    case fw::kPacketBadLength: return "length field does not match";
    case fw::kPacketBadCrc: return "CRC-32 does not match";
    default: return "bad";
  }
}

}  // namespace

ConsoleClient::ConsoleClient(SerialPort& port, std::chrono::milliseconds timeout) : port_(port), timeout_(timeout) {}

std::string ConsoleClient::timeout_seconds() const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", static_cast<double>(timeout_.count()) / 1000.0);
  return seconds;
}

void ConsoleClient::silence() const {
  throw std::runtime_error("the console said nothing for " + timeout_seconds() +
                           " s (is the firmware running the console?)");
}

bool ConsoleClient::next_byte_within(std::chrono::milliseconds wait, uint8_t* byte) {
  if (pos_ == buf_.size()) {
    buf_.resize(4096);
    const size_t n = port_.read_some(buf_.data(), buf_.size(), wait);
    buf_.resize(n);
    pos_ = 0;
    if (n == 0) return false;
  }
  *byte = buf_[pos_++];
  return true;
}

uint8_t ConsoleClient::next_byte() {
  uint8_t b = 0;
  if (!next_byte_within(timeout_, &b)) silence();
  return b;
}

void ConsoleClient::StreamBound::feed(uint8_t byte, std::chrono::milliseconds extend) {
  ++bytes;
  fw::Packet packet;
  if (fw::packet_feed(&decoder, byte, &packet) == fw::kPacketReady)
    deadline = std::max(deadline, std::chrono::steady_clock::now() + extend);
}

void ConsoleClient::no_prompt_in_stream(const StreamBound& bound) const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - bound.start).count());
  throw std::runtime_error("the port kept sending (" + std::to_string(bound.bytes) + " bytes in " + seconds +
                           " s) without a console prompt and a pause after it: is the console on this "
                           "port, at this baud rate?");
}

void ConsoleClient::no_prompt_after(const std::string& seen) const {
  std::string shown;
  for (size_t i = 0; i < seen.size() && i < 32; ++i) {
    const unsigned char c = static_cast<unsigned char>(seen[i]);
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", c);
    shown += (c >= 0x20 && c < 0x7F && c != '"') ? std::string(1, static_cast<char>(c)) : std::string(hex);
  }
  throw std::runtime_error("no console prompt: the port sent " + std::to_string(seen.size()) + " bytes (\"" + shown +
                           (seen.size() > 32 ? "...\"" : "\"") + "), then nothing for " + timeout_seconds() +
                           " s (an echo of what htx sent? is the console on this port, at this baud rate?)");
}

bool ConsoleClient::prompt_within(std::chrono::milliseconds wait, std::string* text, StreamBound* bound) {
  while (!ends_with(*text, kPrompt)) {
    if (text->size() > kMaxText) throw std::runtime_error("the console sent more than 1 MiB without a prompt");
    if (bound && std::chrono::steady_clock::now() > bound->deadline) no_prompt_in_stream(*bound);
    uint8_t b = 0;
    if (!next_byte_within(wait, &b)) return false;
    *text += static_cast<char>(b);
    if (bound) bound->feed(b, timeout_);
  }
  return true;
}

std::string ConsoleClient::read_until_prompt() {
  std::string text;
  if (!prompt_within(timeout_, &text)) silence();
  return text.substr(0, text.size() - std::string(kPrompt).size());
}

void ConsoleClient::sync() {
  // A console answers a line break at once unless it is busy, and a busy console is silent (a
  // render), stops at the key (a spin) or sends packets (the rest of a frame), so a stream of
  // other bytes that outlasts this is not one.
  const auto now = std::chrono::steady_clock::now();
  StreamBound bound{now, now + 2 * timeout_};
  port_.write("\r");
  // A console still receiving an upload whose client ended answers no line break (until its own
  // silence timeout: 10 s on a board, most of a minute on the simulator). After a second of
  // silence without a prompt, an Abort ends such an upload at once; anywhere else the console
  // skips it as a packet frame. Only after silence: a busy console's receive FIFO may be full of
  // unread input, and a byte of the frame lost there would make the console skip what follows.
  std::string text;
  if (!prompt_within(std::min<std::chrono::milliseconds>(kAbortAfter, timeout_), &text, &bound)) {
    std::string seen = std::move(text);
    const uint8_t nothing = 0;
    send_packet(fw::kPacketAbort, 0, &nothing, 1);
    port_.write("\r");
    text.clear();
    if (!prompt_within(timeout_, &text, &bound)) {
      // Bytes without a prompt (an echo of what was sent, a device at another rate) are not the
      // silence of a console that is not running: say what came.
      seen += text;
      if (seen.empty()) silence();
      no_prompt_after(seen);
    }
  }
  // A prompt printed before ours (the greeting's) may be followed by ours: drop everything up to a
  // moment of silence, which a console gives at once after its prompt.
  bound.deadline = std::max(bound.deadline, std::chrono::steady_clock::now() + timeout_);
  for (size_t i = pos_; i < buf_.size(); ++i) bound.feed(buf_[i], timeout_);
  pos_ = buf_.size();
  uint8_t drop[256];
  while (const size_t n = port_.read_some(drop, sizeof drop, kSettle)) {
    for (size_t i = 0; i < n; ++i) bound.feed(drop[i], timeout_);
    if (std::chrono::steady_clock::now() > bound.deadline) no_prompt_in_stream(bound);
  }
}

bool ConsoleClient::read_text_until(const std::string& needle, std::string* text) {
  text->clear();
  for (;;) {
    if (text->size() > kMaxText) throw std::runtime_error("the console sent more than 1 MiB without a prompt");
    *text += static_cast<char>(next_byte());
    if (ends_with(*text, needle)) return true;
    if (ends_with(*text, kPrompt)) {
      text->resize(text->size() - std::string(kPrompt).size());
      return false;
    }
  }
}

fw::PacketStatus ConsoleClient::next_packet(fw::Packet* p) {
  for (;;) {
    const fw::PacketStatus st = fw::packet_feed(&decoder_, next_byte(), p);
    if (st != fw::kPacketNone) return st;
  }
}

ConsoleClient::Answer ConsoleClient::next_answer(fw::Packet* p, std::string* text) {
  // The console's text has no zero byte; a packet is framed by zeros. Text since the last zero
  // that ends with a line end and the prompt is the console's own (a packet's bytes match it with
  // a chance of about 2^-56).
  const std::string line_and_prompt = std::string("\r\n") + kPrompt;
  text->clear();
  for (;;) {
    const uint8_t b = next_byte();
    if (b == 0) {
      text->clear();
    } else {
      if (text->size() > kMaxText) throw std::runtime_error("the console sent more than 1 MiB without a prompt");
      *text += static_cast<char>(b);
    }
    const fw::PacketStatus st = fw::packet_feed(&decoder_, b, p);
    if (st == fw::kPacketReady) return Answer::kPacket;
    if (st != fw::kPacketNone) return Answer::kDamaged;
    if (ends_with(*text, line_and_prompt)) {
      decoder_ = {};
      text->resize(text->size() - std::string(kPrompt).size());
      return Answer::kConsolePrompt;
    }
  }
}

void ConsoleClient::send_packet(uint8_t type, uint8_t seq, const uint8_t* data, size_t len) {
  std::string line(fw::kPacketMaxLine, '\0');
  line.resize(fw::packet_encode(type, seq, data, len, reinterpret_cast<uint8_t*>(line.data())));
  port_.write(line);
}

std::string ConsoleClient::command(const std::string& line) {
  std::string out;
  converse(line, [&out](const std::string& text) { out += text; });
  return out;
}

void ConsoleClient::converse(const std::string& line, const std::function<void(const std::string&)>& show,
                             const std::function<bool()>& stop) {
  if (line.find_first_of("\r\n") != std::string::npos) throw std::invalid_argument("a command is one line");
  // Other control bytes are the console's own keys: a zero starts a packet frame (the console skips
  // up to a frame's length after it, lines and all) and Ctrl-C ends the line early (its answer and
  // the rest's would come out of step with the commands).
  for (const char c : line)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
      throw std::invalid_argument("a command holds no control characters (byte " +
                                  std::to_string(static_cast<unsigned char>(c)) + ")");
  port_.write(line + "\r");
  using Clock = std::chrono::steady_clock;
  const std::string prompt = kPrompt;
  bool echo = true;      // the line's echo, up to its line break, is not shown
  bool stopped = false;  // the stop key went
  std::string held;      // the line being received, shown once it ends (it may be the prompt)
  size_t received = 0;
  Clock::time_point heard = Clock::now(), polled = heard;
  for (;;) {
    uint8_t b = 0;
    const bool got = next_byte_within(kStopPoll, &b);
    const Clock::time_point now = Clock::now();
    // Asked on the clock, not only in silences: a spin's lines come faster than kStopPoll apart.
    if (!stopped && stop && now - polled >= kStopPoll) {
      polled = now;
      if (stop()) {
        port_.write("\r");
        stopped = true;
      }
    }
    if (!got) {
      if (now - heard > timeout_) silence();
      continue;
    }
    heard = now;
    if (++received > kMaxText) throw std::runtime_error("the console sent more than 1 MiB without a prompt");
    if (b == '\r') continue;
    if (echo) {
      echo = b != '\n';
      continue;
    }
    held += static_cast<char>(b);
    if (ends_with(held, prompt)) {
      held.resize(held.size() - prompt.size());
      if (!held.empty()) show(held);
      if (stopped) read_until_prompt();  // the stop key's empty line
      return;
    }
    if (b == '\n') {
      show(held);
      held.clear();
    }
  }
}

void ConsoleClient::set_baud(unsigned baud) {
  // A rate this end cannot take is refused before the console is asked: it would switch, and the
  // two ends would be left at different rates.
  SerialPort::check_baud(baud);
  port_.write("baud " + std::to_string(baud) + "\r");
  std::string text;
  // The answer ends with `ok ... baud` and its line end, or (a refusal) with the prompt.
  if (!read_text_until("baud\r\n", &text)) {
    std::string why = unix_lines(without_echo(text));
    while (!why.empty() && why.back() == '\n') why.pop_back();
    throw std::invalid_argument(why);
  }
  port_.set_baud(baud);
  const std::string rest = read_until_prompt();
  if (!rest.empty()) throw std::runtime_error("baud: the console sent more than its prompt at the new rate: " + rest);
}

GrabbedFrame ConsoleClient::grab(const std::function<void(size_t)>& progress) {
  port_.write("grab\r");
  // The echo and any message come as text; the packets start at the first zero byte.
  std::string text;
  if (!read_text_until(std::string(1, '\0'), &text))
    throw std::runtime_error("grab: the console sent no frame: " + answer_of(text));
  decoder_ = {};
  GrabbedFrame f;
  std::vector<uint8_t> coded;
  uint32_t frame_crc = 0;
  int expect_seq = -1;
  bool have_info = false;
  for (;;) {
    fw::Packet p;
    const fw::PacketStatus st = next_packet(&p);
    if (st != fw::kPacketReady) throw std::runtime_error(std::string("grab: a packet arrived damaged: ") + status_name(st));
    if (expect_seq >= 0 && p.seq != expect_seq)
      throw std::runtime_error("grab: packet " + std::to_string(expect_seq) + " is missing (got " +
                               std::to_string(p.seq) + ")");
    expect_seq = (p.seq + 1) & 0xFF;
    if (!have_info) {
      if (p.type != fw::kPacketFrameInfo || p.len < 10) throw std::runtime_error("grab: the frame's header is missing");
      f.width = static_cast<int>(fw::get_le16(p.payload));
      f.height = static_cast<int>(fw::get_le16(p.payload + 2));
      if (p.payload[4] != 0 || p.payload[5] != 1)
        throw std::runtime_error("grab: unknown pixel format or coding (" + std::to_string(p.payload[4]) + ", " +
                                 std::to_string(p.payload[5]) + ")");
      if (f.width < 1 || f.height < 1 || f.width > 4096 || f.height > 4096)
        throw std::runtime_error("grab: impossible frame size " + std::to_string(f.width) + "x" + std::to_string(f.height));
      frame_crc = fw::get_le32(p.payload + 6);
      have_info = true;
    } else if (p.type == fw::kPacketFrameData) {
      coded.insert(coded.end(), p.payload, p.payload + p.len);
      if (coded.size() > fw::rle16_max_size(static_cast<size_t>(f.width) * static_cast<size_t>(f.height)))
        throw std::runtime_error("grab: more coded bytes than a " + std::to_string(f.width) + "x" +
                                 std::to_string(f.height) + " frame can take");
      ++f.data_packets;
      if (progress) progress(coded.size());
    } else if (p.type == fw::kPacketFrameEnd && p.len >= 8) {
      if (fw::get_le32(p.payload) != f.data_packets || fw::get_le32(p.payload + 4) != coded.size())
        throw std::runtime_error("grab: the frame ended after " + std::to_string(f.data_packets) + " packets and " +
                                 std::to_string(coded.size()) + " bytes, but the console sent " +
                                 std::to_string(fw::get_le32(p.payload)) + " and " +
                                 std::to_string(fw::get_le32(p.payload + 4)));
      break;
    } else {
      throw std::runtime_error("grab: unexpected packet type " + std::to_string(p.type));
    }
  }
  read_until_prompt();
  const size_t count = static_cast<size_t>(f.width) * static_cast<size_t>(f.height);
  f.pixels.resize(count);
  if (fw::rle16_decode(coded.data(), coded.size(), f.pixels.data(), count) != static_cast<long>(count))
    throw std::runtime_error("grab: the pixels do not decode to a " + std::to_string(f.width) + "x" +
                             std::to_string(f.height) + " frame");
  uint32_t reg = fw::kCrc32Init;
  for (uint16_t px : f.pixels) {
    reg = fw::crc32_update_byte(reg, static_cast<uint8_t>(px & 0xFF));
    reg = fw::crc32_update_byte(reg, static_cast<uint8_t>(px >> 8));
  }
  if (~reg != frame_crc) throw std::runtime_error("grab: the frame's CRC-32 does not match its pixels");
  f.crc32 = frame_crc;
  f.coded_bytes = coded.size();
  return f;
}

std::string ConsoleClient::upload(const std::vector<uint8_t>& bytes, const std::function<void(size_t)>& progress,
                                  Payload payload, unsigned slot) {
  const bool texture = payload == Payload::kTexture;
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x", fw::crc32(bytes.data(), bytes.size()));
  const std::string slot_word = texture && slot != 0 ? " " + std::to_string(slot) : "";
  port_.write((texture ? "texture " : "upload ") + std::to_string(bytes.size()) + " " + crc + slot_word + "\r");
  // The console answers `ready`, or refuses with a message and a prompt.
  std::string text;
  if (!read_text_until("ready\r\n", &text))
    throw std::invalid_argument("upload: the console refused: " + answer_of(text));
  decoder_ = {};
  // The console's verdict (its text before the prompt), taken as the transfer's end.
  const auto verdict_of = [](const std::string& said) {
    std::string v = unix_lines(said);
    while (!v.empty() && v.front() == '\n') v.erase(v.begin());
    if (v.find("error:") != std::string::npos) throw std::invalid_argument("upload: " + v);
    return v;
  };
  size_t sent = 0;
  for (uint32_t seq = 0; sent < bytes.size(); ++seq) {
    const size_t len = std::min(fw::kPacketMaxPayload, bytes.size() - sent);
    const bool last = sent + len == bytes.size();
    bool taken = false;
    for (int attempt = 0; attempt < kUploadTries && !taken; ++attempt) {
      if (attempt > 0) ++resent_;
      send_packet(fw::kPacketSceneData, static_cast<uint8_t>(seq), bytes.data() + sent, len);
      for (bool resend = false; !taken && !resend;) {
        fw::Packet answer;
        const Answer a = next_answer(&answer, &text);
        if (a == Answer::kConsolePrompt) {
          // The console ended the transfer: its verdict on the whole (the last packet's Ack was
          // lost on the way), or its own error (it waited too long for a packet).
          const std::string v = verdict_of(text);  // throws on the console's error
          if (!last)  // (the line is at a prompt: the line's error, as the refusals)
            throw std::invalid_argument("upload: the console ended the transfer at packet " + std::to_string(seq) +
                                     " of " + std::to_string((bytes.size() + fw::kPacketMaxPayload - 1) /
                                                             fw::kPacketMaxPayload) + ": " + v);
          if (progress) progress(bytes.size());
          return v;
        }
        if (a == Answer::kDamaged || answer.len < 1) {
          // A damaged answer: send again, but not the last packet, which the console may have
          // taken (it would then read the copy as a typed line): its verdict or its timeout's
          // error comes as text.
          resend = !last;
          continue;
        }
        // An answer to the packet before (a repeat's Ack, sent before this packet arrived) is
        // stale: read on.
        if (answer.type == fw::kPacketAck && seq > 0 && answer.payload[0] == static_cast<uint8_t>(seq - 1)) continue;
        taken = answer.type == fw::kPacketAck && answer.payload[0] == static_cast<uint8_t>(seq);
        resend = !taken;
      }
    }
    if (!taken) {
      const uint8_t nothing = 0;
      send_packet(fw::kPacketAbort, 0, &nothing, 1);
      read_until_prompt();
      throw std::invalid_argument("upload: packet " + std::to_string(seq) + " was not taken after " +
                                  std::to_string(kUploadTries) + " tries; the console's " +
                                  (texture ? "texture" : "scene") + " is unchanged");
    }
    sent += len;
    if (progress) progress(sent);
  }
  return verdict_of(read_until_prompt());
}

}  // namespace htx::console
