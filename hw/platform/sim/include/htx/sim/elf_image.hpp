// A small ELF32 (little-endian RISC-V executable) reader: the loadable segments and the symbol
// table, which is all the SoC harness needs (load the image, find tohost and the signature, name
// the functions a profile charges).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace htx::sim {

struct ElfSegment {
  uint32_t addr = 0;           // physical (load) address
  uint32_t mem_size = 0;       // bytes in memory; those past bytes.size() are zero (.bss)
  std::vector<uint8_t> bytes;  // file contents
};

// A function symbol: STT_FUNC, or an untyped label in an executable section (an assembly entry
// point, often without a size), defined in a section (not absolute).
struct ElfFunction {
  std::string name;  // as in the symbol table (mangled for C++)
  uint32_t addr = 0;
  uint32_t size = 0;  // bytes of code; 0 when the symbol does not say
  uint64_t section_end = 0;  // where its section ends (bounds one without a size); 0: unknown
};

struct ElfImage {
  uint32_t entry = 0;
  std::vector<ElfSegment> segments;
  std::map<std::string, uint32_t> symbols;  // defined symbols by name
  std::vector<ElfFunction> functions;       // defined functions, in symbol-table order

  std::optional<uint32_t> symbol(const std::string& name) const;
};

// Parses an ELF32 RISC-V executable. Throws std::runtime_error naming `what` and the problem for
// anything that is not one (wrong magic, class, endianness or machine, truncated tables).
ElfImage parse_elf(std::span<const uint8_t> data, const std::string& what);
// The largest ELF file load_elf reads: far above any firmware with its debug sections (the
// console's is under 1 MiB), far below what would exhaust a host's memory.
inline constexpr uintmax_t kMaxElfFileBytes = uintmax_t{256} << 20;
// Reads and parses a regular file of at most kMaxElfFileBytes; errors name the path.
ElfImage load_elf(const std::string& path);

// The RAM's contents once the image is loaded at address 0: ram_bytes / 4 little-endian words, zero
// wherever no segment's file bytes land (.bss and the rest). Throws std::runtime_error for a segment
// that does not fit in [0, ram_bytes). ram_bytes must be a multiple of 4. The simulated SoC loads
// its RAM from this; `htx image` writes it for a board's RAM initialisation.
std::vector<uint32_t> ram_words(const ElfImage& image, uint32_t ram_bytes);

// The words as a $readmemh file: one word a line, 8 lower-case hex digits.
std::string readmemh_text(std::span<const uint32_t> words);

}  // namespace htx::sim
