#include "frame_download.hpp"

#include "frame_crc.hpp"
#include "htx/fw/console_packet.h"
#include "htx/fw/rle16.h"
#include "htx/hal/framebuffer.h"
#include "packet_out.hpp"

namespace console_app {

namespace {

constexpr uint32_t kMaxRow = 256;  // rows are read and coded in pieces of this many pixels

struct PacketSender {
  uint8_t seq = 0;
  uint8_t payload[htx::fw::kPacketMaxPayload];
  uint32_t fill = 0;
  uint32_t data_packets = 0, coded_bytes = 0;

  void send(uint8_t type, const uint8_t* data, uint32_t len) { send_packet(type, seq++, data, len); }
  void append(const uint8_t* data, uint32_t len) {
    coded_bytes += len;
    for (uint32_t i = 0; i < len; ++i) {
      payload[fill++] = data[i];
      if (fill == sizeof payload) flush();
    }
  }
  void flush() {
    if (fill == 0) return;
    send(htx::fw::kPacketFrameData, payload, fill);
    ++data_packets;
    fill = 0;
  }
};

}  // namespace

void send_frame(uint32_t width, uint32_t height) {
  PacketSender tx;
  uint8_t info[12];
  htx::fw::put_le16(info, width);
  htx::fw::put_le16(info + 2, height);
  info[4] = 0;  // RGB565
  info[5] = 1;  // RLE16
  htx::fw::put_le32(info + 6, render_app::frame_crc32(width, height));
  tx.send(htx::fw::kPacketFrameInfo, info, 10);

  uint16_t row[kMaxRow];
  uint8_t coded[htx::fw::rle16_max_size(kMaxRow)];
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x0 = 0; x0 < width; x0 += kMaxRow) {
      const uint32_t n = width - x0 < kMaxRow ? width - x0 : kMaxRow;
      htx::hal::fb_read_row(width, y, x0, n, row);
      tx.append(coded, static_cast<uint32_t>(htx::fw::rle16_encode(row, n, coded)));
    }
  tx.flush();
  uint8_t end[8];
  htx::fw::put_le32(end, tx.data_packets);
  htx::fw::put_le32(end + 4, tx.coded_bytes);
  tx.send(htx::fw::kPacketFrameEnd, end, 8);
}

}  // namespace console_app
