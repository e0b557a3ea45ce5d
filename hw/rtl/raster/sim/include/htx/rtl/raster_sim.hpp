// The Verilated raster subsystem (htx_raster_full / htx_raster_icebreaker: raster unit plus
// framebuffer and depth memories) driven through its two bus slave ports, one clock at a time.
// Used by the `rtl` engine (render_rtl) and by the tests in tests/rtl/raster.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace htx::rtl {

class RasterPort;  // the Verilated top behind a common interface (raster_sim.cpp)

// One fragment on the raster's texture request port (docs/contracts.md, GPU join §1), as the loop-back of
// htx_raster_subsys takes it; fields sign-extended from their RTL widths.
struct TexRequest {
  int64_t u = 0, v = 0;            // level-0 texels incl. the offset, TF fraction bits (CoordW bits)
  uint8_t filter = 0, wrap_u = 0, wrap_v = 0, slot = 0;
  uint64_t lod_q = 0;              // max(Q, 1)
  int64_t lod_g[6] = {};           // g_ux, g_uy, g_vx, g_vy, g_qx, g_qy after the block shift
  uint32_t lod_shift = 0;
  int64_t lod_u = 0, lod_v = 0;    // local coordinates (before the offset)
  uint32_t addr = 0;               // the fragment's framebuffer address (from the tag)
};

class RasterSim {
 public:
  // config: "full" or "icebreaker" (the Verilated configurations, as rtl_config), or
  // "icebreaker_untextured" (`icebreaker` built without texture mapping: it draws
  // untextured triangles as "icebreaker" does and refuses textured ones). Throws
  // std::invalid_argument for any other name. Resets the subsystem.
  explicit RasterSim(const std::string& config);
  ~RasterSim();
  RasterSim(const RasterSim&) = delete;
  RasterSim& operator=(const RasterSim&) = delete;

  // Framebuffer and depth memory size in pixels (the 1 MiB depth window: 262144).
  static constexpr uint32_t kFbPixels = 262144;

  // Register access at RASTER (offset from the peripheral base). Each call runs until the response
  // (std::runtime_error if the request is not taken within 2^26 clocks: a deadlock, not a wait).
  // read_reg and write_reg ignore the response's error flag; reg_read and reg_write return it, as
  // the CPU sees it (a write to the full FIFO while CTRL.ENABLE is 0, say).
  uint32_t read_reg(uint32_t offset);
  void write_reg(uint32_t offset, uint32_t value);
  bool reg_read(uint32_t offset, uint32_t* data);
  bool reg_write(uint32_t offset, uint32_t value);

  // Pushes words into the FIFO register back to back, one per clock while the FIFO has room; a
  // full FIFO holds the bus write (back-pressure) and the loop keeps the word presented until it is
  // taken. gap_every/gap_cycles insert idle clocks between words (a slow writer).
  void push_words(const std::vector<uint32_t>& words, unsigned gap_every = 0, unsigned gap_cycles = 0);

  // Clocks until STATUS.BUSY is 0 (polling STATUS). Throws std::runtime_error after max_cycles.
  void wait_idle(uint64_t max_cycles = 2'000'000'000ull);

  // Reads n pixels from address 0 of the colour and depth windows (pipelined bus reads).
  std::vector<uint16_t> read_color(uint32_t n);
  std::vector<uint32_t> read_depth(uint32_t n);

  // Raw memory bus access (framebuffer windows); returns the response's error flag.
  bool mem_read(uint32_t addr, uint32_t* data);
  bool mem_write(uint32_t addr, uint32_t data, uint8_t be = 0xF);

  void idle(uint64_t cycles);  // clocks with no bus request
  uint64_t cycles() const { return cycles_; }
  // Clocks a bus write to FIFO was held (not accepted) since construction.
  uint64_t fifo_stall_cycles() const { return fifo_stall_cycles_; }

  // Records every texture request the loop-back accepts from now on (in order) into *out, or stops
  // recording with nullptr.
  void record_requests(std::vector<TexRequest>* out);

 private:
  void tick();
  std::unique_ptr<RasterPort> port_;
  uint64_t cycles_ = 0;
  uint64_t fifo_stall_cycles_ = 0;
};

}  // namespace htx::rtl
