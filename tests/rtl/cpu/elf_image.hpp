// Minimal ELF32 little-endian RISC-V loader for the CPU testbench: loadable segments and symbols.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace htx::cpu_tb {

struct ElfSegment {
  uint32_t addr = 0;
  std::vector<uint8_t> bytes;  // file contents followed by zeros up to p_memsz
};

struct ElfImage {
  uint32_t entry = 0;
  std::vector<ElfSegment> segments;
  std::map<std::string, uint32_t> symbols;

  std::optional<uint32_t> symbol(const std::string& name) const;
};

// Throws std::runtime_error with a message naming the file and the problem.
ElfImage load_elf(const std::string& path);

}  // namespace htx::cpu_tb
