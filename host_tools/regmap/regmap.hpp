// The register map: parsed from hw/regs/*.json (format in docs/regmap-format.md) and validated.
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace htx::regmap {

enum class Access { RO, WO, RW, RW1C, RC };

struct Field {
  std::string name;
  unsigned lsb = 0;
  unsigned width = 1;
  Access access = Access::RW;
  uint32_t reset = 0;  // value of the field itself (not shifted)
  std::string description;

  uint32_t mask() const { return (width >= 32 ? 0xFFFFFFFFu : ((1u << width) - 1u)) << lsb; }
};

struct Register {
  std::string name;
  uint32_t offset = 0;
  Access access = Access::RW;  // RO, WO or RW: the CMSIS qualifier
  std::string description;
  std::vector<Field> fields;

  uint32_t reset() const;
};

struct Peripheral {
  std::string name;
  uint32_t base = 0;
  std::string description;
  std::string source;  // file it came from, for messages
  std::vector<Register> registers;  // sorted by offset
};

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* access_name(Access a);
// "UART" -> "uart": the file stem of a peripheral's JSON and of its generated names.
std::string lower_name(std::string name);
// "htx_uart_reg_pkg": the SV package name, also the generated file's stem.
std::string sv_package_name(const Peripheral& p);

// Parses and validates one file; throws Error naming the file and register on any problem.
Peripheral load_peripheral(const std::filesystem::path& file);
// Validates a whole map (unique names and bases); peripherals come back sorted by base.
std::vector<Peripheral> load_map(const std::vector<std::filesystem::path>& files);

void emit_c_header(std::ostream& os, const std::vector<Peripheral>& map);
void emit_sv_package(std::ostream& os, const Peripheral& p);
void emit_markdown(std::ostream& os, const std::vector<Peripheral>& map);

}  // namespace htx::regmap
