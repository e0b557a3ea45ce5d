// Standalone testbench of htx_cpu: 64 KiB of memory at 0 on both bus ports (with optional random
// wait states), a SYSCTRL-compatible exit/putchar page, the `tohost` exit convention and a cycle
// limit. Exit status: 0 pass, 1 test failure, 2 cycle limit or testbench/protocol error.
//
//   htx_cpu_tb --elf FILE [--seed S] [--max-cycles N] [--print-words SYMBOL:COUNT]...
//   --seed 0 (default) runs without wait states; any other seed inserts random ones.

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "Vhtx_cpu.h"
#include "Vhtx_cpu___024root.h"
#include "bus_port_model.hpp"
#include "htx/sim/elf_image.hpp"
#include "verilated.h"

namespace {

using htx::cpu_tb::BusPortModel;
using htx::cpu_tb::BusRequest;
using htx::cpu_tb::BusResponse;

constexpr uint32_t kRamBytes = 64 * 1024;
// SYSCTRL simulation ports, from hw/regs/sysctrl.json.
constexpr uint32_t kSysctrlBase = 0x2000'0000;
constexpr uint32_t kSimExit = kSysctrlBase + 0x14;
constexpr uint32_t kSimPutchar = kSysctrlBase + 0x18;

struct Options {
  std::string elf;
  uint64_t seed = 0;
  uint64_t max_cycles = 2'000'000;
  std::vector<std::pair<std::string, uint32_t>> print_words;
};

[[noreturn]] void usage_error(const std::string& msg) {
  std::fprintf(stderr, "htx_cpu_tb: %s\nusage: htx_cpu_tb --elf FILE [--seed S] [--max-cycles N] "
                       "[--print-words SYMBOL:COUNT]...\n", msg.c_str());
  std::exit(2);
}

uint64_t parse_number(const std::string& s, const char* what) {
  char* end = nullptr;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 0);
  if (s.empty() || *end != '\0') usage_error(std::string("bad number for ") + what + ": '" + s + "'");
  return v;
}

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error("missing value after " + a);
      return argv[++i];
    };
    if (a == "--elf") {
      o.elf = value();
    } else if (a == "--seed") {
      o.seed = parse_number(value(), "--seed");
    } else if (a == "--max-cycles") {
      o.max_cycles = parse_number(value(), "--max-cycles");
    } else if (a == "--print-words") {
      const std::string v = value();
      const auto colon = v.find(':');
      if (colon == std::string::npos) usage_error("--print-words wants SYMBOL:COUNT");
      o.print_words.emplace_back(v.substr(0, colon),
                                 static_cast<uint32_t>(parse_number(v.substr(colon + 1), "--print-words")));
    } else if (a.rfind("+verilator", 0) == 0) {
      // Verilator's own runtime options pass through.
    } else {
      usage_error("unknown option " + a);
    }
  }
  if (o.elf.empty()) usage_error("--elf is required");
  return o;
}

class System {
 public:
  explicit System(const htx::sim::ElfImage& image) : ram_(kRamBytes, 0) {
    // The RAM as the SoC harness loads it (a segment that does not fit is refused there).
    const std::vector<uint32_t> words = htx::sim::ram_words(image, kRamBytes);
    std::memcpy(ram_.data(), words.data(), kRamBytes);  // little-endian host, as the bus
    if (auto t = image.symbol("tohost")) tohost_ = *t;
  }

  // Performs one transferred request; returns {rdata, err}.
  std::pair<uint32_t, bool> access(const BusRequest& r) {
    const uint32_t word = r.addr & ~3u;
    if (word < kRamBytes) {
      uint32_t value;
      std::memcpy(&value, ram_.data() + word, 4);
      if (r.we) {
        for (int lane = 0; lane < 4; ++lane) {
          if (r.be & (1u << lane)) ram_[word + lane] = static_cast<uint8_t>(r.wdata >> (8 * lane));
        }
        if (tohost_ && word == *tohost_ && r.wdata != 0) finish_tohost(r.wdata);
        return {0, false};
      }
      return {value, false};
    }
    if ((word & ~0xFFFu) == kSysctrlBase) {
      if (r.we && word == kSimExit) finish_exit(r.wdata & 0xFF);
      if (r.we && word == kSimPutchar) std::fputc(static_cast<int>(r.wdata & 0xFF), stdout);
      return {0, false};
    }
    return {0, true};  // unmapped: access fault
  }

  uint32_t read_word(uint32_t addr) const {
    uint32_t v = 0;
    if (addr + 4 <= kRamBytes) std::memcpy(&v, ram_.data() + addr, 4);
    return v;
  }

  bool finished() const { return finished_; }
  int status() const { return status_; }
  const std::string& verdict() const { return verdict_; }

  static std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x", v);
    return buf;
  }

 private:
  void finish_tohost(uint32_t value) {
    finished_ = true;
    if (value == 1) {
      status_ = 0;
      verdict_ = "PASS (tohost)";
    } else {
      status_ = 1;
      verdict_ = "FAIL (tohost=0x" + hex(value) + ", test " + std::to_string(value >> 1) + ")";
    }
  }
  void finish_exit(uint32_t code) {
    finished_ = true;
    status_ = code == 0 ? 0 : 1;
    verdict_ = code == 0 ? "PASS (SIM_EXIT 0)" : "FAIL (SIM_EXIT " + std::to_string(code) + ")";
  }

  std::vector<uint8_t> ram_;
  std::optional<uint32_t> tohost_;
  bool finished_ = false;
  int status_ = 0;
  std::string verdict_;
};

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse_options(argc, argv);
  try {
    const auto image = htx::sim::load_elf(opt.elf);
    System sys(image);
    auto ctx = std::make_unique<VerilatedContext>();
    ctx->commandArgs(argc, argv);
    auto top = std::make_unique<Vhtx_cpu>(ctx.get());
    // Different streams for the two ports so their stalls are independent.
    BusPortModel ibus("ibus", opt.seed == 0 ? 0 : opt.seed * 2 + 1);
    BusPortModel dbus("dbus", opt.seed == 0 ? 0 : opt.seed * 2 + 2);

    top->clk_i = 0;
    top->rst_ni = 0;
    top->eval();
    top->clk_i = 1;
    top->eval();
    top->rst_ni = 1;
    top->eval();

    uint64_t cycle = 0;
    while (!sys.finished() && cycle < opt.max_cycles) {
      bool iready = false;
      bool dready = false;
      BusResponse irsp, drsp;
      ibus.drive(cycle, iready, irsp);
      dbus.drive(cycle, dready, drsp);
      top->ibus_req_ready_i = iready;
      top->ibus_rsp_valid_i = irsp.valid;
      top->ibus_rsp_rdata_i = irsp.rdata;
      top->ibus_rsp_err_i = irsp.err;
      top->dbus_req_ready_i = dready;
      top->dbus_rsp_valid_i = drsp.valid;
      top->dbus_rsp_rdata_i = drsp.rdata;
      top->dbus_rsp_err_i = drsp.err;
      // The falling edge comes after the slaves' outputs of this cycle, as on a real bus: the
      // core writes its register file on it (htx_cpu_regfile).
      top->clk_i = 0;
      top->eval();

      const BusRequest ireq{top->ibus_req_valid_o != 0, top->ibus_req_addr_o, top->ibus_req_we_o != 0,
                            static_cast<uint8_t>(top->ibus_req_be_o), top->ibus_req_wdata_o};
      const BusRequest dreq{top->dbus_req_valid_o != 0, top->dbus_req_addr_o, top->dbus_req_we_o != 0,
                            static_cast<uint8_t>(top->dbus_req_be_o), top->dbus_req_wdata_o};
      if (auto r = ibus.sample(cycle, ireq)) {
        if (r->we) throw std::runtime_error("ibus: write request at cycle " + std::to_string(cycle));
        const auto [rdata, err] = sys.access(*r);
        ibus.respond(cycle, rdata, err);
      }
      if (auto r = dbus.sample(cycle, dreq)) {
        const auto [rdata, err] = sys.access(*r);
        dbus.respond(cycle, rdata, err);
      }
      top->clk_i = 1;
      top->eval();
      ++cycle;
    }

    const uint64_t instret = top->rootp->htx_cpu__DOT__u_csr__DOT__instret_q;
    for (const auto& [name, count] : opt.print_words) {
      const auto addr = image.symbol(name);
      if (!addr) throw std::runtime_error("--print-words: no symbol '" + name + "' in " + opt.elf);
      for (uint32_t i = 0; i < count; ++i) {
        std::printf("%s[%u] = %u (0x%08x)\n", name.c_str(), i, sys.read_word(*addr + 4 * i),
                    sys.read_word(*addr + 4 * i));
      }
    }
    std::printf("cycles %llu instret %llu cpi %.3f\n", static_cast<unsigned long long>(cycle),
                static_cast<unsigned long long>(instret),
                instret ? static_cast<double>(cycle) / static_cast<double>(instret) : 0.0);
    if (!sys.finished()) {
      std::printf("TIMEOUT: cycle limit %llu reached without an exit (fetch address 0x%08x)\n",
                  static_cast<unsigned long long>(opt.max_cycles), top->ibus_req_addr_o);
      return 2;
    }
    std::printf("%s\n", sys.verdict().c_str());
    top->final();
    return sys.status();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "htx_cpu_tb: error: %s\n", e.what());
    return 2;
  }
}
