#include "elf_image.hpp"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace htx::cpu_tb {
namespace {

template <typename T>
T read_at(const std::vector<uint8_t>& file, uint64_t offset, const std::string& path) {
  if (offset + sizeof(T) > file.size()) {
    throw std::runtime_error(path + ": truncated ELF (offset " + std::to_string(offset) + ")");
  }
  T value;
  std::memcpy(&value, file.data() + offset, sizeof(T));
  return value;
}

}  // namespace

std::optional<uint32_t> ElfImage::symbol(const std::string& name) const {
  auto it = symbols.find(name);
  if (it == symbols.end()) return std::nullopt;
  return it->second;
}

ElfImage load_elf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (file.size() < 52 || std::memcmp(file.data(), "\x7f" "ELF", 4) != 0) {
    throw std::runtime_error(path + ": not an ELF file");
  }
  if (file[4] != 1 || file[5] != 1) throw std::runtime_error(path + ": not a little-endian ELF32 file");
  if (read_at<uint16_t>(file, 18, path) != 243) throw std::runtime_error(path + ": not a RISC-V ELF");

  ElfImage image;
  image.entry = read_at<uint32_t>(file, 24, path);
  const uint32_t phoff = read_at<uint32_t>(file, 28, path);
  const uint32_t shoff = read_at<uint32_t>(file, 32, path);
  const uint16_t phentsize = read_at<uint16_t>(file, 42, path);
  const uint16_t phnum = read_at<uint16_t>(file, 44, path);
  const uint16_t shentsize = read_at<uint16_t>(file, 46, path);
  const uint16_t shnum = read_at<uint16_t>(file, 48, path);

  for (uint32_t i = 0; i < phnum; ++i) {
    const uint64_t ph = uint64_t{phoff} + uint64_t{i} * phentsize;
    if (read_at<uint32_t>(file, ph, path) != 1) continue;  // PT_LOAD only
    const uint32_t offset = read_at<uint32_t>(file, ph + 4, path);
    const uint32_t paddr = read_at<uint32_t>(file, ph + 12, path);
    const uint32_t filesz = read_at<uint32_t>(file, ph + 16, path);
    const uint32_t memsz = read_at<uint32_t>(file, ph + 20, path);
    if (memsz == 0) continue;
    if (uint64_t{offset} + filesz > file.size() || filesz > memsz) {
      throw std::runtime_error(path + ": segment " + std::to_string(i) + " exceeds the file");
    }
    ElfSegment seg;
    seg.addr = paddr;
    seg.bytes.assign(file.begin() + offset, file.begin() + offset + filesz);
    seg.bytes.resize(memsz, 0);
    image.segments.push_back(std::move(seg));
  }

  // Symbols: find SHT_SYMTAB and its string table.
  for (uint32_t i = 0; i < shnum; ++i) {
    const uint64_t sh = uint64_t{shoff} + uint64_t{i} * shentsize;
    if (read_at<uint32_t>(file, sh + 4, path) != 2) continue;  // SHT_SYMTAB
    const uint32_t sym_off = read_at<uint32_t>(file, sh + 16, path);
    const uint32_t sym_size = read_at<uint32_t>(file, sh + 20, path);
    const uint32_t link = read_at<uint32_t>(file, sh + 24, path);
    const uint64_t strsh = uint64_t{shoff} + uint64_t{link} * shentsize;
    const uint32_t str_off = read_at<uint32_t>(file, strsh + 16, path);
    const uint32_t str_size = read_at<uint32_t>(file, strsh + 20, path);
    for (uint32_t s = 0; s + 16 <= sym_size; s += 16) {
      const uint32_t name = read_at<uint32_t>(file, uint64_t{sym_off} + s, path);
      const uint32_t value = read_at<uint32_t>(file, uint64_t{sym_off} + s + 4, path);
      if (name == 0 || name >= str_size) continue;
      const char* str = reinterpret_cast<const char*>(file.data() + str_off + name);
      const size_t max_len = str_size - name;
      image.symbols.emplace(std::string(str, strnlen(str, max_len)), value);
    }
  }
  return image;
}

}  // namespace htx::cpu_tb
