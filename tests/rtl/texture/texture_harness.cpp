#include "texture_harness.hpp"

#include <random>
#include <stdexcept>

#include "Vhtx_texture_full.h"
#include "Vhtx_texture_icebreaker.h"
#include "htx/model/texture.hpp"
#include "htx/rtl/two_port_pins.hpp"
#include "verilated.h"

namespace htx::rtl {

namespace {
constexpr uint32_t kMemBase = 0x40000000u;
constexpr uint32_t kRegBase = 0x20004000u;
uint64_t mask_bits(int64_t v, unsigned bits) {
  return bits >= 64 ? static_cast<uint64_t>(v) : static_cast<uint64_t>(v) & ((uint64_t{1} << bits) - 1);
}
}  // namespace

// Both configurations share every port name; this hides which one runs.
class TexturePort {
 public:
  virtual ~TexturePort() = default;
  using Bus = htx::rtl::PortRequest;
  Bus reg, mem;
  bool req_valid = false, out_ready = true;
  TexRequest req;
  uint32_t req_tag = 0;
  // Outputs after settle() (clock low).
  bool reg_ready = false, mem_ready = false, req_ready = false, out_valid = false;
  bool reg_rsp_valid = false, mem_rsp_valid = false, mem_rsp_err = false;
  uint32_t reg_rdata = 0, mem_rdata = 0;
  TexResult out;
  unsigned coord_bits = 0;

  virtual void settle() = 0;
  virtual void rise() = 0;
};

namespace {

template <class V>
class Port final : public TexturePort {
 public:
  Port(unsigned cw, unsigned qw, unsigned gw, unsigned lw)
      : ctx_(std::make_unique<VerilatedContext>()), top_(std::make_unique<V>(ctx_.get())), qw_(qw), gw_(gw),
        lw_(lw) {
    coord_bits = cw;
    top_->rst_ni = 0;
    top_->clk_i = 0;
    top_->eval();
    top_->rst_ni = 1;
    top_->eval();
  }
  ~Port() override { top_->final(); }

  void settle() override {
    htx::rtl::drive_requests(*top_, reg, mem);
    top_->req_valid_i = req_valid;
    top_->req_u_i = mask_bits(req.u, coord_bits);
    top_->req_v_i = mask_bits(req.v, coord_bits);
    top_->req_filter_i = static_cast<unsigned>(req.filter);
    top_->req_wrap_u_i = static_cast<unsigned>(req.wrap_u);
    top_->req_wrap_v_i = static_cast<unsigned>(req.wrap_v);
    top_->req_slot_i = req.slot & 0xFF;
    top_->req_lod_direct_i = req.lod_direct;
    top_->req_lod_i = static_cast<uint32_t>(mask_bits(req.lod, 24));
    top_->req_lod_q_i = mask_bits(static_cast<int64_t>(req.q), qw_);
    top_->req_lod_gux_i = mask_bits(req.g[0], gw_);
    top_->req_lod_guy_i = mask_bits(req.g[1], gw_);
    top_->req_lod_gvx_i = mask_bits(req.g[2], gw_);
    top_->req_lod_gvy_i = mask_bits(req.g[3], gw_);
    top_->req_lod_gqx_i = mask_bits(req.g[4], gw_);
    top_->req_lod_gqy_i = mask_bits(req.g[5], gw_);
    top_->req_lod_shift_i = req.grad_shift & 0xFF;
    top_->req_lod_u_i = mask_bits(req.lu, lw_);
    top_->req_lod_v_i = mask_bits(req.lv, lw_);
    top_->req_tag_i = req_tag;
    top_->out_ready_i = out_ready;
    top_->clk_i = 0;
    top_->eval();
    reg_ready = top_->reg_req_ready_o;
    mem_ready = top_->mem_req_ready_o;
    req_ready = top_->req_ready_o;
    out_valid = top_->out_valid_o;
    reg_rsp_valid = top_->reg_rsp_valid_o;
    reg_rdata = top_->reg_rsp_rdata_o;
    mem_rsp_valid = top_->mem_rsp_valid_o;
    mem_rsp_err = top_->mem_rsp_err_o;
    mem_rdata = top_->mem_rsp_rdata_o;
    out.rgba = top_->out_rgba_o;
    out.level = top_->out_level_o;
    out.lod = top_->out_lod_o;
    out.tag = static_cast<uint32_t>(top_->out_tag_o);
  }
  void rise() override {
    top_->clk_i = 1;
    top_->eval();
  }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
  unsigned qw_, gw_, lw_;
};

}  // namespace

TextureHarness::TextureHarness(const std::string& config) {
  if (config == "full")
    port_ = std::make_unique<Port<Vhtx_texture_full>>(48, 58, 24, 32);
  else if (config == "icebreaker")
    port_ = std::make_unique<Port<Vhtx_texture_icebreaker>>(20, 42, 16, 23);
  else
    throw std::invalid_argument("TextureHarness: unknown configuration " + config);
}
TextureHarness::~TextureHarness() = default;

unsigned TextureHarness::coord_bits() const { return port_->coord_bits; }

void TextureHarness::tick() {
  port_->settle();
  port_->rise();
}

namespace {

// Holds the request just placed on one of the port's channels (reg or mem) until the unit accepts it,
// for at most `limit` clocks, then drops its valid.
void hold_until_accepted(TexturePort& p, TexturePort::Bus TexturePort::*channel, bool TexturePort::*ready,
                         int limit) {
  for (int i = 0; i < limit; ++i) {
    p.settle();
    const bool done = p.*ready;
    p.rise();
    if (done) break;
  }
  (p.*channel).valid = false;
}

}  // namespace

void TextureHarness::reg_write(uint32_t offset, uint32_t value) {
  TexturePort& p = *port_;
  p.reg = htx::rtl::write_at(kRegBase + offset, value);
  hold_until_accepted(p, &TexturePort::reg, &TexturePort::reg_ready, 100);
  tick();
}

uint32_t TextureHarness::reg_read(uint32_t offset) {
  TexturePort& p = *port_;
  p.reg = htx::rtl::read_at(kRegBase + offset);
  hold_until_accepted(p, &TexturePort::reg, &TexturePort::reg_ready, 100);
  for (int i = 0; i < 100; ++i) {
    p.settle();
    if (p.reg_rsp_valid) {
      const uint32_t v = p.reg_rdata;
      p.rise();
      return v;
    }
    p.rise();
  }
  throw std::runtime_error("reg_read: no response");
}

bool TextureHarness::mem_write(uint32_t offset, uint32_t value, uint8_t be) {
  TexturePort& p = *port_;
  p.mem = htx::rtl::write_at(kMemBase + offset, value, be);
  hold_until_accepted(p, &TexturePort::mem, &TexturePort::mem_ready, 1000);
  p.settle();
  const bool err = p.mem_rsp_err;
  if (!p.mem_rsp_valid) throw std::runtime_error("mem_write: no response");
  p.rise();
  return err;
}

bool TextureHarness::mem_read(uint32_t offset, uint32_t* value) {
  TexturePort& p = *port_;
  p.mem = htx::rtl::read_at(kMemBase + offset);
  hold_until_accepted(p, &TexturePort::mem, &TexturePort::mem_ready, 1000);
  p.settle();
  if (!p.mem_rsp_valid) throw std::runtime_error("mem_read: no response");
  *value = p.mem_rdata;
  const bool err = p.mem_rsp_err;
  p.rise();
  return err;
}

uint32_t tex_level_offset(unsigned a, unsigned b, unsigned level) {
  uint32_t off = 0;
  for (unsigned l = 0; l < level; ++l) {
    const unsigned sa = a > l + 1 ? a - l - 1 : 0, sb = b > l + 1 ? b - l - 1 : 0;
    off += uint32_t{1} << (sa + sb);
  }
  return off;
}

uint32_t tex_texel_offset(const Texture& tex, uint32_t base, unsigned level, unsigned i, unsigned j) {
  const unsigned lw = level_log2_width(tex, level);
  const uint32_t stride = lw > 0 ? uint32_t{1} << (lw - 1) : 1;
  const uint32_t block = base + tex_level_offset(tex.log2_width, tex.log2_height, level) + (j >> 1) * stride + (i >> 1);
  return 4 * (4 * block + 2 * (j & 1) + (i & 1));
}

uint32_t TextureHarness::upload(const Texture& tex, unsigned slot, uint32_t base) {
  const unsigned n = level_count(tex);
  for (unsigned l = 0; l < n; ++l) {
    const unsigned w = 1u << level_log2_width(tex, l), h = 1u << level_log2_height(tex, l);
    for (unsigned j = 0; j < h; ++j)
      for (unsigned i = 0; i < w; ++i)
        if (mem_write(tex_texel_offset(tex, base, l, i, j), tex.levels[l][j * w + i]))
          throw std::runtime_error("upload: texture does not fit the memory");
  }
  reg_write(0x100 + 4 * slot, (base & 0xFFFF) | (tex.log2_width << 16) | (tex.log2_height << 20) |
                                  (static_cast<uint32_t>(tex.format) << 24));
  return tex_level_offset(tex.log2_width, tex.log2_height, n);
}

std::vector<TexResult> TextureHarness::run(const std::vector<TexRequest>& reqs, unsigned stall_permille,
                                           uint32_t seed, TexRunStats* stats, TexRunReads* reads) {
  TexturePort& p = *port_;
  std::mt19937 rng(seed);
  std::vector<TexResult> out;
  out.reserve(reqs.size());
  size_t next = 0, read_next = 0;
  const bool reading = reads && !reads->offsets.empty();
  uint64_t cycle = 0, first = 0, last = 0;
  bool started = false;
  const uint64_t limit = 64 * reqs.size() + 1000;
  while (out.size() < reqs.size()) {
    if (cycle > limit) throw std::runtime_error("run: the unit stopped answering");
    p.req_valid = next < reqs.size();
    if (p.req_valid) {
      p.req = reqs[next];
      p.req_tag = static_cast<uint32_t>(next);
    }
    p.out_ready = stall_permille == 0 || (rng() % 1000) >= stall_permille;
    if (reading) p.reg = htx::rtl::read_at(kRegBase + reads->offsets[read_next % reads->offsets.size()]);
    p.settle();
    const bool in_fire = p.req_valid && p.req_ready;
    if (reading) {
      if (p.reg_rsp_valid) reads->values.push_back(p.reg_rdata);  // the read accepted last clock
      if (p.reg_ready) ++read_next;
      else ++reads->waited;
    }
    if (p.out_valid && p.out_ready) {
      out.push_back(p.out);
      last = cycle;
    }
    if (in_fire && !started) {
      started = true;
      first = cycle;
    }
    p.rise();
    if (in_fire) ++next;
    ++cycle;
  }
  p.req_valid = false;
  p.out_ready = true;
  p.reg.valid = false;
  p.settle();
  if (reading && p.reg_rsp_valid) reads->values.push_back(p.reg_rdata);  // the last read's response
  p.rise();
  if (stats) stats->cycles = last - first + 1;
  return out;
}

}  // namespace htx::rtl
