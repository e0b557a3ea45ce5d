// Robustness of the SoC harness's ELF reader (hw/platform/sim/elf_image.cpp, compiled into this
// test with the address and undefined-behaviour sanitizers): every truncation, bit flips, header
// fields set to extreme values, and random files. Each input either parses, with segments whose
// bytes come from inside the file, or is refused with std::runtime_error naming the input and the
// problem ("not a usable RISC-V ELF32 executable: ..."). Nothing else may happen.
// (`htx sim` at --max-cycles on firmware that never exits is covered by tests/system.)
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "htx/sim/elf_image.hpp"

namespace {

void put16(std::vector<uint8_t>& b, size_t off, uint16_t v) {
  b[off] = static_cast<uint8_t>(v);
  b[off + 1] = static_cast<uint8_t>(v >> 8);
}
void put32(std::vector<uint8_t>& b, size_t off, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[off + i] = static_cast<uint8_t>(v >> (8 * i));
}

// A small but complete RISC-V ELF32 executable: two PT_LOAD segments (text; data with .bss),
// a symbol table with tohost, begin_signature and end_signature, and its string table.
std::vector<uint8_t> seed_elf() {
  std::vector<uint8_t> b(52 + 2 * 32, 0);
  const size_t text = b.size();
  for (uint32_t i = 0; i < 8; ++i) {  // eight instructions' worth of bytes
    b.resize(b.size() + 4);
    put32(b, b.size() - 4, 0x00000013u + (i << 7));
  }
  const size_t data = b.size();
  b.resize(b.size() + 16, 0xAB);
  const size_t strtab = b.size();
  const std::string names = std::string("\0tohost\0begin_signature\0end_signature\0", 38);
  b.insert(b.end(), names.begin(), names.end());
  const size_t symtab = (b.size() + 3) & ~size_t{3};
  b.resize(symtab + 4 * 16, 0);
  const uint32_t name_off[3] = {1, 8, 24};
  const uint32_t value[3] = {0x1000, 0x1004, 0x1010};
  for (int i = 0; i < 3; ++i) {
    const size_t s = symtab + 16 * (i + 1);
    put32(b, s, name_off[i]);
    put32(b, s + 4, value[i]);
    put16(b, s + 14, 2);  // defined in section 2
  }
  const size_t shoff = b.size();
  b.resize(shoff + 3 * 40, 0);
  // Section 1: .symtab, linked to section 2 (.strtab).
  put32(b, shoff + 40 + 4, 2);
  put32(b, shoff + 40 + 16, static_cast<uint32_t>(symtab));
  put32(b, shoff + 40 + 20, 4 * 16);
  put32(b, shoff + 40 + 24, 2);
  put32(b, shoff + 40 + 36, 16);
  put32(b, shoff + 80 + 4, 3);  // SHT_STRTAB
  put32(b, shoff + 80 + 16, static_cast<uint32_t>(strtab));
  put32(b, shoff + 80 + 20, static_cast<uint32_t>(names.size()));
  // ELF header.
  std::memcpy(b.data(), "\x7f" "ELF", 4);
  b[4] = 1;  // ELFCLASS32
  b[5] = 1;  // little-endian
  b[6] = 1;
  put16(b, 16, 2);    // ET_EXEC
  put16(b, 18, 243);  // EM_RISCV
  put32(b, 20, 1);
  put32(b, 24, 0);    // entry
  put32(b, 28, 52);   // phoff
  put32(b, 32, static_cast<uint32_t>(shoff));
  put16(b, 40, 52);
  put16(b, 42, 32);
  put16(b, 44, 2);
  put16(b, 46, 40);
  put16(b, 48, 3);
  // Program headers.
  const size_t ph0 = 52, ph1 = 84;
  put32(b, ph0, 1);
  put32(b, ph0 + 4, static_cast<uint32_t>(text));
  put32(b, ph0 + 12, 0);
  put32(b, ph0 + 16, 32);
  put32(b, ph0 + 20, 32);
  put32(b, ph1, 1);
  put32(b, ph1 + 4, static_cast<uint32_t>(data));
  put32(b, ph1 + 12, 0x1000);
  put32(b, ph1 + 16, 16);
  put32(b, ph1 + 20, 64);
  return b;
}

// Parses; returns true if accepted. Any exception but runtime_error with the documented prefix fails.
bool try_parse(const std::vector<uint8_t>& file, const std::string& what) {
  try {
    const htx::sim::ElfImage img = htx::sim::parse_elf(file, "input");
    EXPECT_FALSE(img.segments.empty()) << what;
    for (const auto& s : img.segments) EXPECT_LE(s.bytes.size(), s.mem_size) << what;
    for (size_t i = 0; i < img.segments.size(); ++i)
      for (size_t j = 0; j < i; ++j) {
        const auto &a = img.segments[i], &b = img.segments[j];
        EXPECT_TRUE(uint64_t{a.addr} + a.mem_size <= b.addr || uint64_t{b.addr} + b.mem_size <= a.addr)
            << what << ": segments overlap";
      }
    // Loaded into a RAM as the simulator and `htx image` load it: it fits, or is refused in words.
    try {
      const std::vector<uint32_t> ram = htx::sim::ram_words(img, 64 * 1024);
      EXPECT_EQ(ram.size(), 16u * 1024u) << what;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("does not fit in the 65536-byte RAM at 0"), std::string::npos)
          << what << ": " << e.what();
    }
    return true;
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("input: not a usable RISC-V ELF32 executable: ", 0), 0u) << what << ": " << msg;
    return false;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": unexpected exception " << e.what();
    return false;
  }
}

TEST(ElfFuzz, SeedParses) {
  const std::vector<uint8_t> seed = seed_elf();
  const htx::sim::ElfImage img = htx::sim::parse_elf(seed, "seed");
  ASSERT_EQ(img.segments.size(), 2u);
  EXPECT_EQ(img.segments[1].addr, 0x1000u);
  EXPECT_EQ(img.segments[1].mem_size, 64u);
  EXPECT_EQ(img.symbol("tohost"), 0x1000u);
  EXPECT_EQ(img.symbol("end_signature"), 0x1010u);
}

// A segment whose file bytes have no memory, or two segments sharing an address, would leave out
// bytes or leave it to their order which win.
TEST(ElfFuzz, SegmentsThatWouldLoseOrMixBytesAreRefused) {
  const size_t ph1 = 84;
  std::vector<uint8_t> no_memory = seed_elf();
  put32(no_memory, ph1 + 20, 0);  // data: 16 bytes in the file, memsz 0
  std::vector<uint8_t> overlapping = seed_elf();
  put32(overlapping, ph1 + 12, 0x10);  // data at 0x10, inside the text's 32 bytes
  const std::pair<const std::vector<uint8_t>*, const char*> cases[] = {
      {&no_memory, "a segment's file size exceeds its memory size"},
      {&overlapping, "two loadable segments overlap"},
  };
  for (const auto& [file, message] : cases) {
    try {
      htx::sim::parse_elf(*file, "input");
      ADD_FAILURE() << "accepted; expected: " << message;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  std::vector<uint8_t> adjacent = seed_elf();
  put32(adjacent, ph1 + 12, 0x20);  // right after the text: accepted
  EXPECT_EQ(htx::sim::parse_elf(adjacent, "adjacent").segments.size(), 2u);
}

// e_flags for compressed instructions, a hardware floating-point ABI or RV32E: the CPU is rv32im
// (an RVC build ran no instruction at all until the cycle limit); TSO (0x10) changes nothing here.
TEST(ElfFuzz, ElfsBuiltForAnotherIsaOrAbiAreRefused) {
  const std::pair<uint32_t, const char*> cases[] = {
      {0x1, "built for compressed instructions (e_flags RVC)"},
      {0x2, "built for a hardware floating-point ABI"},
      {0x4, "built for a hardware floating-point ABI"},
      {0x6, "built for a hardware floating-point ABI"},
      {0x8, "built for RV32E"},
      {0x5, "built for compressed instructions"},
  };
  for (const auto& [flags, message] : cases) {
    std::vector<uint8_t> f = seed_elf();
    put32(f, 36, flags);
    try {
      htx::sim::parse_elf(f, "input");
      ADD_FAILURE() << "e_flags 0x" << std::hex << flags << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  std::vector<uint8_t> tso = seed_elf();
  put32(tso, 36, 0x10);
  EXPECT_EQ(htx::sim::parse_elf(tso, "tso").segments.size(), 2u);
}

TEST(ElfFuzz, EveryTruncationIsRefusedOrComplete) {
  const std::vector<uint8_t> seed = seed_elf();
  for (size_t n = 0; n < seed.size(); ++n) {
    const std::vector<uint8_t> cut(seed.begin(), seed.begin() + static_cast<std::ptrdiff_t>(n));
    const bool ok = try_parse(cut, "truncated to " + std::to_string(n));
    // The section table is last: every cut into it or earlier must be refused.
    EXPECT_FALSE(ok) << "truncated to " << n << " bytes of " << seed.size() << " was accepted";
  }
}

TEST(ElfFuzz, BitFlips) {
  const std::vector<uint8_t> seed = seed_elf();
  std::mt19937 rng(11);
  int accepted = 0;
  for (int iter = 0; iter < 20000; ++iter) {
    std::vector<uint8_t> f = seed;
    for (unsigned k = 1 + rng() % 8; k > 0; --k) f[rng() % f.size()] ^= static_cast<uint8_t>(1u << (rng() % 8));
    accepted += try_parse(f, "bit flips " + std::to_string(iter));
    if (::testing::Test::HasFailure()) FAIL() << "iteration " << iter;
  }
  EXPECT_GT(accepted, 100);  // many flips hit bytes that do not matter
}

TEST(ElfFuzz, ExtremeHeaderFields) {
  const std::vector<uint8_t> seed = seed_elf();
  std::mt19937 rng(12);
  // Offsets of every 16- and 32-bit field the reader uses (ELF header, both program headers, the
  // symbol and string table section headers, the symbols).
  const size_t f32[] = {24, 28, 32, 52 + 4, 52 + 12, 52 + 16, 52 + 20, 84 + 4, 84 + 16, 84 + 20};
  const size_t f16[] = {42, 44, 46, 48};
  const uint32_t extremes[] = {0, 1, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu, 0xFFFFFFF0u, 0x10000u};
  const size_t shoff = seed.size() - 120;
  for (int iter = 0; iter < 20000; ++iter) {
    std::vector<uint8_t> f = seed;
    for (unsigned k = 1 + rng() % 3; k > 0; --k) {
      const uint32_t v = (rng() % 2) ? extremes[rng() % 7] : rng();
      switch (rng() % 4) {
        case 0: put32(f, f32[rng() % 10], v); break;
        case 1: put16(f, f16[rng() % 4], static_cast<uint16_t>(v)); break;
        case 2: put32(f, shoff + 40 + 4 * (rng() % 10), v); break;   // symtab section header
        default: put32(f, shoff + 80 + 4 * (rng() % 10), v); break;  // strtab section header
      }
    }
    try_parse(f, "extreme fields " + std::to_string(iter));
    if (::testing::Test::HasFailure()) FAIL() << "iteration " << iter;
  }
}

TEST(ElfFuzz, RandomFiles) {
  std::mt19937 rng(13);
  const std::vector<uint8_t> seed = seed_elf();
  for (int iter = 0; iter < 5000; ++iter) {
    std::vector<uint8_t> f(rng() % 600);
    for (auto& b : f) b = static_cast<uint8_t>(rng());
    if (iter % 2 && f.size() >= 20) std::memcpy(f.data(), seed.data(), 20);  // a valid-looking start
    EXPECT_FALSE(try_parse(f, "random " + std::to_string(iter)) && iter % 2 == 0);
    if (::testing::Test::HasFailure()) FAIL() << "iteration " << iter;
  }
}

TEST(ElfFuzz, LoadElfNamesAMissingFile) {
  try {
    htx::sim::load_elf("/nonexistent/dir/firmware.elf");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/firmware.elf"), std::string::npos);
  }
}

}  // namespace
