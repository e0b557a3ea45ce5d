// Reading a whole input file that a user names: only a regular file, and only up to a limit, so
// that a device (/dev/zero) or a pipe is refused rather than read until memory runs out.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace htx::host {

// The bytes of the regular file `path` of at most `max_bytes`. Throws std::runtime_error with the
// reason alone ("not a regular file", the size against the limit, a short read); callers name
// the file in their own words.
inline std::string read_regular_file(const std::string& path, uintmax_t max_bytes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error("not a regular file");
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error("cannot read its size: " + ec.message());
  if (size > max_bytes)
    throw std::runtime_error(std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) + " read");
  std::string bytes(static_cast<size_t>(size), '\0');
  std::ifstream in(path, std::ios::binary);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw std::runtime_error("read " + std::to_string(in.gcount()) + " of its " + std::to_string(size) + " bytes");
  return bytes;
}

}  // namespace htx::host
