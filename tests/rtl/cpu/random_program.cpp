#include "random_program.hpp"

#include <array>
#include <cstdlib>
#include <random>
#include <utility>
#include <vector>

namespace htx::cpu_tb {
namespace {

constexpr int kLinkReg = 1;    // calls' return address: a subroutine never writes it
constexpr int kLogReg = 29;    // the result log's pointer: nothing else writes it
constexpr int kLoopReg = 30;   // the counted loops' counter: nothing else writes it
constexpr int kBaseReg = 31;   // the data region's middle: nothing writes it
// x31 = data + 512, so every byte of the region and of the checkpoints after it is a 12-bit offset
constexpr int kDataMid = 512;
constexpr int kDataBytes = static_cast<int>(kRandomProgramDataWords) * 4;
constexpr int kMainBlocks = 240;
constexpr uint32_t kLogPercent = 30;
static_assert(1024 - kDataMid + kRandomProgramCheckpoints * kRandomProgramRegWords * 4 <= 2048,
              "the last checkpoint word is beyond a 12-bit offset from the base");

// Values that reach the edge cases: zero, one, all ones, the signed extremes (DIV's overflow),
// and the byte and half-word sign boundaries (the load lanes' extension).
constexpr std::array<uint32_t, 12> kSpecialValues = {
    0, 1, 2, 0xFFFFFFFF, 0x80000000, 0x7FFFFFFF, 0xFFFF8000, 0x00008000, 0x0000FFFF,
    0x000000FF, 0x00000080, 0xFFFFFF7F};
constexpr std::array<int32_t, 8> kSpecialImmediates = {0, 1, -1, 2, 2047, -2048, 0x7F0, -0x800 + 1};

constexpr std::array<const char*, 10> kRegRegOps = {"add", "sub", "sll", "slt", "sltu",
                                                   "xor", "srl", "sra", "or",  "and"};
constexpr std::array<const char*, 6> kRegImmOps = {"addi", "slti", "sltiu", "xori", "ori", "andi"};
constexpr std::array<const char*, 3> kShiftImmOps = {"slli", "srli", "srai"};
constexpr std::array<const char*, 8> kMulDivOps = {"mul", "mulh", "mulhsu", "mulhu",
                                                   "div", "divu", "rem",    "remu"};
constexpr std::array<const char*, 3> kMulHighOps = {"mulh", "mulhsu", "mulhu"};
constexpr std::array<const char*, 4> kMulOps = {"mul", "mulh", "mulhsu", "mulhu"};
constexpr std::array<const char*, 6> kBranchOps = {"beq", "bne", "blt", "bge", "bltu", "bgeu"};

// Where a block is generated: a subroutine must not write the return address, and loops and
// calls do not nest (one loop counter, one return address).
struct Scope {
  bool in_loop = false;
  bool in_sub = false;
};

std::string reg(int r) { return "x" + std::to_string(r); }
// A memory operand: "imm(xN)".
std::string at(int imm, int base) { return std::to_string(imm) + "(" + reg(base) + ")"; }
std::string store_op(int size) { return size == 4 ? "sw" : size == 2 ? "sh" : "sb"; }

class Generator {
 public:
  explicit Generator(uint64_t seed) : rng_(seed) {}

  std::string program() {
    constexpr int kEvery = kMainBlocks / static_cast<int>(kRandomProgramCheckpoints);
    for (int i = 0; i < kMainBlocks; ++i) {
      block(Scope{});
      if (i % kEvery == kEvery - 1) checkpoint(i / kEvery);
    }
    line("j .Ldone");
    std::string out = prologue();
    out += "body:\n" + body_;
    for (const std::string& sub : subs_) out += sub;
    out += epilogue();
    out += data();
    return out;
  }

 private:
  uint32_t bits32() { return static_cast<uint32_t>(rng_() >> 32); }
  uint32_t below(uint32_t n) { return static_cast<uint32_t>(rng_() % n); }
  bool chance(uint32_t percent) { return below(100) < percent; }
  template <typename T, size_t N>
  T pick(const std::array<T, N>& options) {
    return options[below(N)];
  }

  uint32_t value() { return chance(50) ? pick(kSpecialValues) : bits32(); }
  int32_t imm12() {
    return chance(40) ? pick(kSpecialImmediates) : static_cast<int32_t>(below(4096)) - 2048;
  }

  // A register to read: often one of the last few written (the forwarding paths and hazards).
  int source() {
    const uint32_t r = below(100);
    if (r < 55) return recent_[below(recent_.size())];
    if (r < 60) return 0;
    if (r < 65) return chance(50) ? kLoopReg : kBaseReg;
    return 1 + static_cast<int>(below(29));
  }
  // A register to write: x0 now and then (the write is dropped), never the log pointer, the loop
  // counter or the base, and not the return address inside a subroutine.
  int dest(const Scope& s) {
    for (;;) {
      int r;
      if (chance(5)) {
        r = 0;
      } else if (chance(30)) {
        r = recent_[below(recent_.size())];
      } else {
        r = 1 + static_cast<int>(below(28));
      }
      if (!(s.in_sub && r == kLinkReg)) return r;
    }
  }
  int nonzero_dest(const Scope& s) {
    for (;;) {
      if (const int r = dest(s); r != 0) return r;
    }
  }
  void wrote(int rd) {
    if (rd == 0) return;
    op_dests_.push_back(rd);
    for (size_t i = recent_.size() - 1; i > 0; --i) recent_[i] = recent_[i - 1];
    recent_[0] = rd;
  }

  // A load of `size` bytes, below a word signed or unsigned at random.
  std::string load_op(int size) {
    if (size == 4) return "lw";
    const bool is_signed = chance(50);
    return size == 2 ? (is_signed ? "lh" : "lhu") : (is_signed ? "lb" : "lbu");
  }

  std::string label() { return ".L" + std::to_string(next_label_++); }
  void line(const std::string& text) { body_ += "  " + text + "\n"; }
  void place(const std::string& name) { body_ += name + ":\n"; }

  void alu_op(const Scope& s) {
    const int rd = dest(s);
    const uint32_t r = below(100);
    if (r < 45) {
      line(std::string(pick(kRegRegOps)) + " " + reg(rd) + ", " + reg(source()) + ", " +
           reg(source()));
    } else if (r < 85) {
      line(std::string(pick(kRegImmOps)) + " " + reg(rd) + ", " + reg(source()) + ", " +
           std::to_string(imm12()));
    } else {
      line(std::string(pick(kShiftImmOps)) + " " + reg(rd) + ", " + reg(source()) + ", " +
           std::to_string(chance(30) ? (chance(50) ? 0 : 31) : below(32)));
    }
    wrote(rd);
  }

  void upper_op(const Scope& s) {
    const int rd = dest(s);
    line(std::string(chance(50) ? "lui " : "auipc ") + reg(rd) + ", " +
         std::to_string(chance(30) ? (chance(50) ? 0 : 0xFFFFF) : below(1u << 20)));
    wrote(rd);
  }

  void load_constant(const Scope& s) {
    const int rd = dest(s);
    line("li " + reg(rd) + ", " + std::to_string(static_cast<int32_t>(value())));
    wrote(rd);
  }

  // MUL/DIV; a divide often gets a divisor of 0, -1 or 1 and a dividend of INT_MIN just before
  // it, written by the instructions in front (so also forwarded into the unit).
  void mul_div_op(const Scope& s) {
    const std::string op = pick(kMulDivOps);
    int a = source();
    int b = source();
    if (op[0] != 'm' && chance(40)) {
      b = dest(s);
      line("li " + reg(b) + ", " + std::to_string(pick(std::array<int32_t, 3>{0, -1, 1})));
      wrote(b);
      if (chance(50)) {
        a = dest(s);
        line("li " + reg(a) + ", -2147483648");
        wrote(a);
      }
    }
    const int rd = dest(s);
    line(op + " " + reg(rd) + ", " + reg(a) + ", " + reg(b));
    wrote(rd);
  }

  // Two or three MUL-class instructions in a row on the same operands, the runs the core fuses
  // (MULH[S][U] and MUL in either order, the same signedness twice, a chain of them) and the ones
  // it must not (other signedness pairs, the operands swapped); now and then the first's
  // destination is one of the operands, which the others must then not share.
  void mul_run(const Scope& s) {
    const int a = source();
    const int b = chance(10) ? a : source();
    int first = dest(s);
    if (chance(25)) first = chance(50) ? a : b;
    if ((s.in_sub && first == kLinkReg) || first >= kLogReg) first = 0;
    line(std::string(chance(50) ? pick(kMulHighOps) : "mul") + " " + reg(first) + ", " + reg(a) +
         ", " + reg(b));
    wrote(first);
    const int more = chance(30) ? 2 : 1;
    for (int i = 0; i < more; ++i) {
      const int rd = dest(s);
      const bool swapped = chance(20);
      line(std::string(pick(kMulOps)) + " " + reg(rd) + ", " + reg(swapped ? b : a) + ", " +
           reg(swapped ? a : b));
      wrote(rd);
    }
  }

  // An aligned access inside the data region, from the base or from an address register written
  // just before (unaligned itself, the offset making it aligned).
  void memory_op(const Scope& s) {
    const int size = 1 << below(3);
    const int offset = static_cast<int>(below(kDataBytes)) / size * size - kDataMid;
    int base = kBaseReg;
    int imm = offset;
    if (chance(40)) {
      base = nonzero_dest(s);
      const int step = static_cast<int>(below(kDataBytes)) - kDataMid;
      line("addi " + reg(base) + ", " + reg(kBaseReg) + ", " + std::to_string(step));
      wrote(base);
      imm = offset - step;
    }
    if (chance(50)) {
      const std::string op = load_op(size);
      const int rd = dest(s);
      line(op + " " + reg(rd) + ", " + at(imm, base));
      wrote(rd);
    } else {
      line(store_op(size) + " " + reg(source()) + ", " + at(imm, base));
    }
  }

  // A store, then a load of the same word in another width or lane.
  void store_load_pair(const Scope& s) {
    const int word = static_cast<int>(below(kDataBytes / 4)) * 4 - kDataMid;
    const int store_size = 1 << below(3);
    const int load_size = 1 << below(3);
    const int store_at = word + static_cast<int>(below(4 / store_size)) * store_size;
    const int load_at = word + static_cast<int>(below(4 / load_size)) * load_size;
    const std::string load = load_op(load_size);
    line(store_op(store_size) + " " + reg(source()) + ", " + at(store_at, kBaseReg));
    const int rd = dest(s);
    line(load + " " + reg(rd) + ", " + at(load_at, kBaseReg));
    wrote(rd);
  }

  // Self-modifying code: an OP-IMM instruction built at run time is stored over the NOP that
  // follows a FENCE.I, which must make the fetch see it (the core's fetch buffer may already hold
  // the NOP). The text is writable: RAM on the core, made so by mprotect for qemu-riscv32.
  void patched_instruction(const Scope& s) {
    const uint32_t funct3 = pick(std::array<uint32_t, 6>{0, 2, 3, 4, 6, 7});
    const int rd = dest(s);
    const uint32_t word = (static_cast<uint32_t>(imm12()) & 0xFFFu) << 20 |
                          static_cast<uint32_t>(source()) << 15 | funct3 << 12 |
                          static_cast<uint32_t>(rd) << 7 | 0x13u;
    const int value = nonzero_dest(s);
    int address = nonzero_dest(s);
    while (address == value) address = nonzero_dest(s);
    const std::string slot = label();
    line("li " + reg(value) + ", " + std::to_string(static_cast<int32_t>(word)));
    line("lla " + reg(address) + ", " + slot);
    line("sw " + reg(value) + ", " + at(0, address));
    line("fence.i");
    place(slot);
    line("nop");
    wrote(value);
    wrote(address);
    wrote(rd);
  }

  // One straight-line operation; in the main body (where each runs at most once, so the log's
  // size is known here) its results often go to the log. Not always: the log's stores between
  // two operations would part most of the pairs that test forwarding.
  void straight(const Scope& s) {
    op_dests_.clear();
    straight_op(s);
    if (s.in_loop || s.in_sub || !chance(kLogPercent)) return;
    for (const int rd : op_dests_) {
      if (log_sites_ == kRandomProgramLogWords) return;
      ++log_sites_;
      line("sw " + reg(rd) + ", " + at(0, kLogReg));
      line("addi " + reg(kLogReg) + ", " + reg(kLogReg) + ", 4");
    }
  }

  void straight_op(const Scope& s) {
    const uint32_t r = below(100);
    if (r < 33) {
      alu_op(s);
    } else if (r < 48) {
      mul_div_op(s);
    } else if (r < 70) {
      memory_op(s);
    } else if (r < 76) {
      load_constant(s);
    } else if (r < 82) {
      upper_op(s);
    } else if (r < 89) {
      mul_run(s);
    } else if (r < 97) {
      store_load_pair(s);
    } else if (r < 99) {
      line(chance(50) ? "fence" : "fence.i");
    } else {
      patched_instruction(s);
    }
  }

  void skipped_run(const Scope& s, uint32_t most) {
    const uint32_t n = 1 + below(most);
    for (uint32_t i = 0; i < n; ++i) straight(s);
  }

  void forward_branch(const Scope& s) {
    const std::string target = label();
    line(std::string(pick(kBranchOps)) + " " + reg(source()) + ", " + reg(source()) + ", " +
         target);
    skipped_run(s, 5);
    place(target);
  }

  // JAL, or JALR through an address register holding the target less JALR's offset (or, with
  // an offset of 1, the target itself, so that JALR clears the sum's bit 0), written just before
  // or stored and loaded back just before (a load's result used by the jump at once); now and
  // then the link register is the address register itself.
  void forward_jump(const Scope& s) {
    const std::string target = label();
    const uint32_t form = below(3);
    if (form == 0) {
      const int rd = dest(s);
      line("jal " + reg(rd) + ", " + target);
      wrote(rd);
    } else {
      const int offset = pick(std::array<int, 5>{0, 0, 1, 8, -8});
      const int address = nonzero_dest(s);
      const int adjust = offset == 1 ? 0 : offset;
      line("lla " + reg(address) + ", " + target +
           (adjust == 0 ? "" : (adjust > 0 ? "-" : "+") + std::to_string(std::abs(adjust))));
      wrote(address);
      int base = address;
      if (form == 2) {
        const std::string word =
            at(static_cast<int>(below(kDataBytes / 4)) * 4 - kDataMid, kBaseReg);
        base = nonzero_dest(s);
        line("sw " + reg(address) + ", " + word);
        line("lw " + reg(base) + ", " + word);
        wrote(base);
      }
      const int rd = chance(25) ? base : dest(s);
      line("jalr " + reg(rd) + ", " + at(offset, base));
      wrote(rd);
    }
    skipped_run(s, 3);
    place(target);
  }

  void loop(const Scope& s) {
    const std::string top = label();
    line("li " + reg(kLoopReg) + ", " + std::to_string(2 + below(5)));
    place(top);
    const Scope inner{true, s.in_sub};
    const uint32_t n = 2 + below(8);
    for (uint32_t i = 0; i < n; ++i) block(inner);
    line("addi " + reg(kLoopReg) + ", " + reg(kLoopReg) + ", -1");
    const uint32_t form = below(3);
    line(form == 0   ? "bnez " + reg(kLoopReg) + ", " + top
         : form == 1 ? "blt x0, " + reg(kLoopReg) + ", " + top
                     : "bne " + reg(kLoopReg) + ", x0, " + top);
  }

  // A call to a subroutine placed after the main body, by JAL or by JALR through an address
  // register (which may be the link register itself); it returns by JALR x0, 0(x1).
  void call(const Scope& s) {
    const std::string name = "sub" + std::to_string(subs_.size());
    if (chance(50)) {
      line("jal " + reg(kLinkReg) + ", " + name);
    } else {
      const int address = nonzero_dest(s);
      line("lla " + reg(address) + ", " + name);
      wrote(address);
      line("jalr " + reg(kLinkReg) + ", " + at(0, address));
    }
    wrote(kLinkReg);
    std::string caller_body;  // the subroutine is written into body_ meanwhile
    std::swap(caller_body, body_);
    place(name);
    const Scope inner{s.in_loop, true};
    const uint32_t n = 1 + below(6);
    for (uint32_t i = 0; i < n; ++i) block(inner);
    line(chance(50) ? "ret" : "jalr x0, 0(x1)");
    std::swap(caller_body, body_);
    subs_.push_back(std::move(caller_body));
  }

  // x0..x31 into checkpoint area k, after the data region.
  void checkpoint(int k) {
    const int first = kDataBytes - kDataMid + k * static_cast<int>(kRandomProgramRegWords) * 4;
    for (int r = 0; r < 32; ++r) line("sw " + reg(r) + ", " + at(first + 4 * r, kBaseReg));
  }

  void block(const Scope& s) {
    const uint32_t r = below(100);
    if (r < 62) {
      straight(s);
    } else if (r < 76) {
      forward_branch(s);
    } else if (r < 84) {
      forward_jump(s);
    } else if (r < 92 && !s.in_loop && !s.in_sub) {
      loop(s);
    } else if (!s.in_sub) {
      call(s);
    } else {
      straight(s);
    }
  }

  // The two variants' own code sits in slots of a fixed size (`.org` refuses a slot that
  // overflows), and the linker does not relax (which shortens address pairs by where their
  // targets land), so that both images put every instruction and data word at the same address.
  std::string prologue() {
    std::string p =
        "#include \"htx_test.h\"\n"  // HTX_SIM_EXIT_ADDR
        "  .option norelax\n"
        "  .section .text.init, \"ax\"\n"
        "  .globl _start\n"
        "_start:\n"
        "#ifndef HTX_QEMU\n"
        "  lla x5, trapped\n"
        "  csrw mtvec, x5\n"
        "#else\n"
        // mprotect(0, text_end, READ | WRITE | EXEC): the linker maps the text read-only, and
        // patched_instruction writes it; exit(2) if that is refused.
        "  li a7, 226\n"
        "  li a0, 0\n"
        "  lla a1, text_end\n"
        "  li a2, 7\n"
        "  ecall\n"
        "  beqz a0, setup\n"
        "  li a7, 93\n"
        "  li a0, 2\n"
        "  ecall\n"
        "#endif\n"
        "  j setup\n"
        "#ifndef HTX_QEMU\n"
        "  .balign 4\n"
        "trapped:\n"
        "  li x5, HTX_SIM_EXIT_ADDR\n"
        "  li x6, " +
        std::to_string(kRandomProgramTrapExit) +
        "\n"
        "  sw x6, 0(x5)\n"
        "1: j 1b\n"
        "#endif\n"
        "  .org _start + 64\n"
        "setup:\n"
        "  lla x31, init_regs\n";
    for (int r = 1; r <= 30; ++r) {
      p += "  lw " + reg(r) + ", " + at(4 * (r - 1), kBaseReg) + "\n";
    }
    p += "  lla " + reg(kLogReg) + ", log\n";
    p += "  lla x31, data + " + std::to_string(kDataMid) + "\n  j body\n";
    return p;
  }

  static std::string epilogue() {
    std::string e = ".Ldone:\n";
    const int regs_at = -kDataMid - static_cast<int>(kRandomProgramRegWords) * 4;
    for (int r = 0; r < 32; ++r) {
      e += "  sw " + reg(r) + ", " + at(regs_at + 4 * r, kBaseReg) + "\n";
    }
    e += "finish:\n"
         "#ifdef HTX_QEMU\n"
         "  li a7, 64\n"  // write(1, sig, size)
         "  li a0, 1\n"
         "  lla a1, sig\n"
         "  li a2, " +
         std::to_string(kRandomProgramSignatureWords * 4) +
         "\n"
         "  ecall\n"
         "  li a7, 93\n"  // exit(0)
         "  li a0, 0\n"
         "  ecall\n"
         "#else\n"
         "  li x5, HTX_SIM_EXIT_ADDR\n"
         "  sw x0, 0(x5)\n"
         "#endif\n"
         "1: j 1b\n"
         "  .org finish + 64\n"
         "text_end:\n";
    return e;
  }

  std::string data() {
    std::string d = "  .data\n  .balign 16\ninit_regs:\n";
    for (int r = 1; r <= 30; ++r) d += "  .word " + std::to_string(value()) + "\n";
    d += "  .balign 16\n  .globl sig\n  .globl begin_signature\nsig:\nbegin_signature:\n  .space " +
         std::to_string(kRandomProgramRegWords * 4) + "\ndata:\n";
    for (uint32_t i = 0; i < kRandomProgramDataWords; ++i) {
      d += "  .word " + std::to_string(value()) + "\n";
    }
    d += "checkpoints:\n  .space " +
         std::to_string(kRandomProgramCheckpoints * kRandomProgramRegWords * 4) + "\n";
    d += "log:\n  .space " + std::to_string(kRandomProgramLogWords * 4) + "\n";
    d += "  .globl end_signature\nend_signature:\n";  // for htx sim --signature
    return d;
  }

  std::mt19937_64 rng_;
  std::string body_;               // the stream being written: the main body or a subroutine
  std::vector<std::string> subs_;  // finished subroutines, placed after the main body
  std::vector<int> op_dests_;      // the registers the current straight-line operation wrote
  uint32_t log_sites_ = 0;         // log stores written (each runs at most once)
  std::array<int, 3> recent_{5, 6, 7};
  int next_label_ = 0;
};

}  // namespace

std::string random_program(uint64_t seed) { return Generator(seed).program(); }

std::string signature_word_name(uint32_t index) {
  if (index < kRandomProgramRegWords) return "x" + std::to_string(index);
  index -= kRandomProgramRegWords;
  if (index < kRandomProgramDataWords) return "data[" + std::to_string(index) + "]";
  index -= kRandomProgramDataWords;
  if (index < kRandomProgramCheckpoints * kRandomProgramRegWords) {
    return "checkpoint " + std::to_string(index / kRandomProgramRegWords) + " x" +
           std::to_string(index % kRandomProgramRegWords);
  }
  return "log[" + std::to_string(index - kRandomProgramCheckpoints * kRandomProgramRegWords) + "]";
}

}  // namespace htx::cpu_tb
