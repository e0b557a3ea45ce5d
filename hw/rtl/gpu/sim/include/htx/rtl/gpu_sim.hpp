// The Verilated GPU (htx_gpu_full / htx_gpu_icebreaker: raster unit, texture unit, framebuffer and
// depth memories) driven through its two bus slave ports, one clock at a time. Used by the `rtl`
// engine (render_rtl) and the tests in tests/rtl/gpu. Addresses are SoC bus addresses
// (docs/contracts.md): RASTER and TEXTURE registers on the register port, the framebuffer, depth
// and texture windows on the memory port.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace htx::rtl {

class GpuPort;  // the Verilated top behind a common interface (gpu_sim.cpp)

class GpuSim {
 public:
  // config: "full" or "icebreaker". Throws std::invalid_argument for any other name. Resets the GPU.
  explicit GpuSim(const std::string& config);
  ~GpuSim();
  GpuSim(const GpuSim&) = delete;
  GpuSim& operator=(const GpuSim&) = delete;

  // Framebuffer and depth memory size in pixels (the 1 MiB depth window: 262144).
  static constexpr uint32_t kFbPixels = 262144;
  static constexpr uint32_t kColorWindow = 0x30000000u;
  static constexpr uint32_t kDepthWindow = 0x30100000u;
  static constexpr uint32_t kTextureWindow = 0x40000000u;

  // Texture memory of the Verilated model in blocks (2x2 texels): 2^TexBAW.
  uint32_t texture_blocks() const { return texture_blocks_; }

  // One register access on the register port (RASTER or TEXTURE, absolute address); runs until the
  // response. read_reg throws std::runtime_error when the response carries rsp_err.
  uint32_t read_reg(uint32_t addr);
  void write_reg(uint32_t addr, uint32_t value);

  // One memory-port access; returns the response's error flag.
  bool mem_read(uint32_t addr, uint32_t* data);
  bool mem_write(uint32_t addr, uint32_t data, uint8_t be = 0xF);
  // Pipelined full-word writes (one per clock while the port is ready); returns how many answered
  // rsp_err.
  uint64_t mem_write_burst(const std::vector<std::pair<uint32_t, uint32_t>>& addr_data);

  // Pushes words into RASTER.FIFO back to back; a full FIFO holds the bus write (back-pressure).
  void push_words(const std::vector<uint32_t>& words);

  // Clocks until RASTER.STATUS.BUSY and TEXTURE.STATUS.BUSY are both 0. Throws std::runtime_error
  // after max_cycles.
  void wait_idle(uint64_t max_cycles = 2'000'000'000ull);

  // Reads n pixels from address 0 of the colour and depth windows (pipelined bus reads).
  std::vector<uint16_t> read_color(uint32_t n);
  std::vector<uint32_t> read_depth(uint32_t n);

  void idle(uint64_t cycles);  // clocks with no bus request
  uint64_t cycles() const { return cycles_; }

 private:
  std::vector<uint32_t> read_words(uint32_t base, uint32_t n);
  std::unique_ptr<GpuPort> port_;
  uint32_t texture_blocks_ = 0;
  uint64_t cycles_ = 0;
};

}  // namespace htx::rtl
