// Drives a Verilated texture unit (either configuration) from C++: register and memory-window bus
// accesses, texture uploads in the unit's memory layout, and streams of sample requests with
// optional output back-pressure. docs/texture.md describes the interface.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "htx/model/types.hpp"

namespace htx::rtl {

struct TexRequest {
  int64_t u = 0, v = 0;  // level-0 texels with the configuration's TF fraction bits, incl. offset
  Filter filter = Filter::Nearest;
  Wrap wrap_u = Wrap::Repeat, wrap_v = Wrap::Repeat;
  unsigned slot = 0;
  bool lod_direct = true;
  int32_t lod = 0;  // direct LOD, LF fraction bits
  // LOD unit inputs (model LodInputs), used when lod_direct is false.
  uint64_t q = 1;
  int64_t g[6] = {0, 0, 0, 0, 0, 0};  // uq x, uq y, vq x, vq y, q x, q y
  unsigned grad_shift = 0;
  int64_t lu = 0, lv = 0;  // local coordinates
};

struct TexResult {
  uint32_t rgba = 0;  // r 7:0 ... a 31:24
  unsigned level = 0;
  unsigned lod = 0;
  uint32_t tag = 0;
};

struct TexRunStats {
  uint64_t cycles = 0;          // from the first request accepted to the last result taken
};

// Register reads issued back to back on the register port while run() streams its requests: the
// offsets in turn, each value as read, and the clocks a read was presented but not accepted.
struct TexRunReads {
  std::vector<uint32_t> offsets;
  std::vector<uint32_t> values;  // one per read completed, in order
  uint64_t waited = 0;
};

class TexturePort;

class TextureHarness {
 public:
  explicit TextureHarness(const std::string& config);  // "full" or "icebreaker"
  ~TextureHarness();

  unsigned coord_bits() const;  // request coordinate width (CoordW)

  void reg_write(uint32_t offset, uint32_t value);
  uint32_t reg_read(uint32_t offset);
  // Memory window access at byte offset; returns rsp_err.
  bool mem_write(uint32_t offset, uint32_t value, uint8_t be = 0xF);
  bool mem_read(uint32_t offset, uint32_t* value);

  // Writes every level of tex starting at block `base` and points descriptor `slot` at it;
  // returns the number of blocks the chain takes.
  uint32_t upload(const Texture& tex, unsigned slot, uint32_t base);

  // Sends the requests in order (tag = index) and returns one result per request in output order.
  // stall_permille: chance per clock that the output is not taken.
  // reads: register reads to issue meanwhile (TexRunReads).
  std::vector<TexResult> run(const std::vector<TexRequest>& reqs, unsigned stall_permille = 0,
                             uint32_t seed = 1, TexRunStats* stats = nullptr, TexRunReads* reads = nullptr);

 private:
  void tick();
  std::unique_ptr<TexturePort> port_;
};

// Blocks before level `level` of a 2^a x 2^b mip chain (2x2 texels per block).
uint32_t tex_level_offset(unsigned a, unsigned b, unsigned level);
// Memory window byte offset of texel (i, j) of a level.
uint32_t tex_texel_offset(const Texture& tex, uint32_t base, unsigned level, unsigned i, unsigned j);

}  // namespace htx::rtl
