// Writing a whole output file, checked to the end: a write error (a full disk, /dev/full, a path
// that is a directory) is an error, not a truncated file reported as written.
#pragma once

#include <string>
#include <string_view>

namespace htx {

// Writes `bytes` to `path` (created or truncated), then closes it, and throws std::runtime_error
// with the path and the system's reason if opening, writing or closing failed.
void write_file(const std::string& path, std::string_view bytes);

}  // namespace htx
