// Output files are checked before the work that fills them (a long simulation, a frame over a serial
// line), so a mistyped path costs nothing: the directory must exist.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace htx {

inline void require_output_dir(const std::string& path) {
  if (path.empty()) return;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw std::runtime_error(path + ": no directory " + dir.string() + " to write it in");
}

}  // namespace htx
