#include "htx/model/file_out.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace htx {

void write_file(const std::string& path, std::string_view bytes) {
  // stdio rather than a stream: fclose's status says whether the buffered tail reached the file.
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  errno = 0;
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const int write_errno = errno;
  errno = 0;
  const bool closed = std::fclose(f) == 0;
  const int why = written ? errno : write_errno;
  if (!written || !closed)
    throw std::runtime_error("cannot write '" + path + "': " + (why != 0 ? std::strerror(why) : "short write"));
}

}  // namespace htx
