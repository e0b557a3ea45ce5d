// ELF32 reader written from the System V ABI / ELF specification field layouts.
#include "htx/sim/elf_image.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "htx/host/file_in.hpp"

namespace htx::sim {
namespace {

constexpr uint16_t kEtExec = 2;
constexpr uint16_t kEmRiscv = 243;
constexpr uint32_t kPtLoad = 1;
constexpr uint32_t kShtSymtab = 2;
constexpr uint16_t kShnUndef = 0;
constexpr uint16_t kShnLoReserve = 0xFF00;  // SHN_ABS, SHN_COMMON, ...: no section
constexpr uint8_t kSttNoType = 0;
constexpr uint8_t kSttFunc = 2;
constexpr uint32_t kShfExecInstr = 4;

class Reader {
 public:
  Reader(std::span<const uint8_t> data, const std::string& what) : data_(data), what_(what) {}

  uint32_t u32(uint64_t off) const { return get(off, 4); }
  uint16_t u16(uint64_t off) const { return static_cast<uint16_t>(get(off, 2)); }
  uint8_t u8(uint64_t off) const { return static_cast<uint8_t>(get(off, 1)); }
  void need(uint64_t off, uint64_t len, const char* part) const {
    if (off > data_.size() || len > data_.size() - off) {
      fail(std::string(part) + " lies outside the file (truncated or corrupt)");
    }
  }
  [[noreturn]] void fail(const std::string& msg) const {
    throw std::runtime_error(what_ + ": not a usable RISC-V ELF32 executable: " + msg);
  }
  std::span<const uint8_t> bytes(uint64_t off, uint64_t len, const char* part) const {
    need(off, len, part);
    return data_.subspan(off, len);
  }

 private:
  uint32_t get(uint64_t off, unsigned n) const {
    need(off, n, "a header field");
    uint32_t v = 0;
    for (unsigned i = 0; i < n; ++i) v |= static_cast<uint32_t>(data_[off + i]) << (8 * i);
    return v;
  }
  std::span<const uint8_t> data_;
  const std::string& what_;
};

}  // namespace

std::optional<uint32_t> ElfImage::symbol(const std::string& name) const {
  auto it = symbols.find(name);
  if (it == symbols.end()) return std::nullopt;
  return it->second;
}

ElfImage parse_elf(std::span<const uint8_t> data, const std::string& what) {
  Reader r(data, what);
  if (data.size() < 4 || std::memcmp(data.data(), "\x7f" "ELF", 4) != 0) {
    r.fail("bad magic (not an ELF file)");
  }
  r.need(0, 52, "the ELF header");
  if (r.u8(4) != 1) r.fail("not ELFCLASS32 (a 64-bit ELF?)");
  if (r.u8(5) != 1) r.fail("not little-endian");
  if (r.u16(16) != kEtExec) r.fail("not an executable (ET_EXEC)");
  if (r.u16(18) != kEmRiscv) r.fail("machine is not RISC-V");
  // e_flags (the RISC-V ELF psABI): an ELF built for compressed instructions, a hardware
  // floating-point ABI or RV32E is refused, since the CPU runs rv32im with the ilp32 ABI; the
  // first would run no instruction at all, the others would call conventions nothing here keeps.
  const uint32_t flags = r.u32(36);
  if (flags & 0x1) r.fail("built for compressed instructions (e_flags RVC); the CPU is rv32im: build with -march=rv32im");
  if (flags & 0x6) r.fail("built for a hardware floating-point ABI (e_flags); the CPU is rv32im: build with -mabi=ilp32");
  if (flags & 0x8) r.fail("built for RV32E (e_flags); the CPU is rv32im");

  ElfImage img;
  img.entry = r.u32(24);
  const uint32_t phoff = r.u32(28);
  const uint32_t shoff = r.u32(32);
  const uint16_t phentsize = r.u16(42);
  const uint16_t phnum = r.u16(44);
  const uint16_t shentsize = r.u16(46);
  const uint16_t shnum = r.u16(48);

  if (phnum != 0 && phentsize < 32) r.fail("program header entries too small");
  r.need(phoff, static_cast<uint64_t>(phnum) * phentsize, "the program header table");
  for (uint16_t i = 0; i < phnum; ++i) {
    const uint64_t ph = phoff + static_cast<uint64_t>(i) * phentsize;
    if (r.u32(ph) != kPtLoad) continue;
    const uint32_t offset = r.u32(ph + 4);
    const uint32_t paddr = r.u32(ph + 12);
    const uint32_t filesz = r.u32(ph + 16);
    const uint32_t memsz = r.u32(ph + 20);
    if (filesz > memsz) r.fail("a segment's file size exceeds its memory size");
    if (memsz == 0) continue;
    ElfSegment seg;
    seg.addr = paddr;
    seg.mem_size = memsz;
    auto b = r.bytes(offset, filesz, "a loadable segment");
    seg.bytes.assign(b.begin(), b.end());
    img.segments.push_back(std::move(seg));
  }
  if (img.segments.empty()) r.fail("no loadable segments");
  // Overlapping segments would leave it to their order which bytes (or which .bss zeros) win.
  std::vector<const ElfSegment*> by_addr;
  for (const ElfSegment& seg : img.segments) by_addr.push_back(&seg);
  std::sort(by_addr.begin(), by_addr.end(), [](auto* a, auto* b) { return a->addr < b->addr; });
  for (size_t i = 1; i < by_addr.size(); ++i)
    if (uint64_t{by_addr[i - 1]->addr} + by_addr[i - 1]->mem_size > by_addr[i]->addr)
      r.fail("two loadable segments overlap");

  if (shnum != 0 && shentsize < 40) r.fail("section header entries too small");
  r.need(shoff, static_cast<uint64_t>(shnum) * shentsize, "the section header table");
  for (uint16_t i = 0; i < shnum; ++i) {
    const uint64_t sh = shoff + static_cast<uint64_t>(i) * shentsize;
    if (r.u32(sh + 4) != kShtSymtab) continue;
    const uint32_t symoff = r.u32(sh + 16);
    const uint32_t symsize = r.u32(sh + 20);
    const uint32_t link = r.u32(sh + 24);
    const uint32_t entsize = r.u32(sh + 36);
    if (entsize < 16) r.fail("symbol table entries too small");
    if (link >= shnum) r.fail("symbol table names a missing string table");
    const uint64_t strsh = shoff + static_cast<uint64_t>(link) * shentsize;
    const uint32_t stroff = r.u32(strsh + 16);
    const uint32_t strsize = r.u32(strsh + 20);
    auto strtab = r.bytes(stroff, strsize, "the string table");
    r.need(symoff, symsize, "the symbol table");
    for (uint64_t s = symoff; s + entsize <= static_cast<uint64_t>(symoff) + symsize; s += entsize) {
      const uint32_t name = r.u32(s);
      const uint32_t value = r.u32(s + 4);
      const uint32_t size = r.u32(s + 8);
      const uint8_t type = r.u8(s + 12) & 0xF;
      const uint16_t shndx = r.u16(s + 14);
      if (shndx == kShnUndef || name == 0 || name >= strtab.size()) continue;
      const auto* begin = reinterpret_cast<const char*>(strtab.data()) + name;
      const size_t len = strnlen(begin, strtab.size() - name);
      img.symbols.emplace(std::string(begin, len), value);
      // Functions: FUNC symbols, and untyped labels in code (assembly entry points such as
      // _start), not absolute symbols (picolibc aliases unused stdio functions to 0 that way) nor
      // the RISC-V mapping symbols ($x..., $d: where code and data begin).
      if (shndx >= kShnLoReserve || (type != kSttFunc && type != kSttNoType) || begin[0] == '$') continue;
      const uint64_t section = shoff + static_cast<uint64_t>(shndx) * shentsize;
      if (shndx >= shnum || !(r.u32(section + 8) & kShfExecInstr)) continue;
      img.functions.push_back(
          {std::string(begin, len), value, size, uint64_t{r.u32(section + 12)} + r.u32(section + 20)});
    }
  }
  return img;
}

std::vector<uint32_t> ram_words(const ElfImage& image, uint32_t ram_bytes) {
  if (ram_bytes % 4 != 0) throw std::runtime_error("RAM size " + std::to_string(ram_bytes) + " is not whole words");
  std::vector<uint32_t> words(ram_bytes / 4, 0);
  for (const ElfSegment& seg : image.segments) {
    if (seg.addr >= ram_bytes || seg.mem_size > ram_bytes - seg.addr) {
      char addr[16];
      std::snprintf(addr, sizeof addr, "0x%08x", seg.addr);
      throw std::runtime_error("ELF segment at " + std::string(addr) + " (" + std::to_string(seg.mem_size) +
                               " bytes) does not fit in the " + std::to_string(ram_bytes) + "-byte RAM at 0");
    }
    for (size_t b = 0; b < seg.bytes.size(); ++b) {
      const uint32_t a = seg.addr + static_cast<uint32_t>(b);
      uint32_t& w = words[a / 4];
      w = (w & ~(0xFFu << (8 * (a % 4)))) | (static_cast<uint32_t>(seg.bytes[b]) << (8 * (a % 4)));
    }
  }
  return words;
}

std::string readmemh_text(std::span<const uint32_t> words) {
  std::string text;
  text.reserve(words.size() * 9);
  char line[10];
  for (uint32_t w : words) {
    std::snprintf(line, sizeof line, "%08x\n", w);
    text += line;
  }
  return text;
}

ElfImage load_elf(const std::string& path) {
  std::string bytes;
  try {
    bytes = host::read_regular_file(path, kMaxElfFileBytes);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what() + " (an ELF for the SoC)");
  }
  return parse_elf(std::span(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), path);
}

}  // namespace htx::sim
