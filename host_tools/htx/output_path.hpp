// Output files are checked before the work that fills them (a long simulation, a frame over a serial
// line), so a mistyped path costs nothing: the directory must exist, the path must not be a
// directory, a new file must be one its directory takes, it must not be the command's
// standard output (which carries its report lines: an image there would be corrupted by them),
// and two outputs of one command must not be the same file.
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <stdexcept>
#include <string>

namespace htx {

inline void require_output_dir(const std::string& path) {
  if (path.empty()) return;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw std::runtime_error(path + ": no directory " + dir.string() + " to write it in");
  if (std::filesystem::is_directory(path)) throw std::runtime_error(path + ": is a directory, not a file to write");
  struct stat out {}, std_out {};
  // Standard output as a file, pipe or socket: the image would be mixed with the report lines. (A
  // device is no such clash: --out /dev/null > /dev/null throws both away.)
  if (::stat(path.c_str(), &out) == 0 && !S_ISCHR(out.st_mode) && ::fstat(STDOUT_FILENO, &std_out) == 0 &&
      out.st_dev == std_out.st_dev && out.st_ino == std_out.st_ino)
    throw std::runtime_error(path + ": is this command's standard output, which carries its report lines; "
                             "give a file of its own");
  // A path where nothing is yet (not even a dangling link) is created once to see that its
  // directory takes a new file (/proc does not), and removed again. What exists is left to its
  // writer: an existing file may be replaced rather than written (the FST writer deletes it
  // first), and a pipe's open would wait.
  struct stat link {};
  if (::lstat(path.c_str(), &link) == 0) return;
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOCTTY | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error(path + ": cannot be written (" + std::strerror(errno) + ")");
  ::close(fd);
  ::unlink(path.c_str());
}

// Whether two output paths name one regular file, existing (also through a link) or to be created.
// Devices are not files written whole: /dev/null twice is two outputs thrown away.
inline bool same_output_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ea, eb;
  const bool a_exists = fs::exists(a, ea), b_exists = fs::exists(b, eb);
  if (a_exists && b_exists) return fs::is_regular_file(a) && fs::equivalent(a, b);
  if (a_exists != b_exists) return false;
  return fs::weakly_canonical(fs::absolute(a)) == fs::weakly_canonical(fs::absolute(b));
}

// A required output given as an empty path (`--out ""`): refused, where require_output_dir reads
// empty as "not asked for".
inline void require_given_path(const std::string& path, const std::string& option) {
  if (path.empty()) throw std::runtime_error(option + ": an empty path is no file to write");
}

// An output that is one of the command's own input files would destroy it: refused.
inline void require_not_input(const std::string& output, const std::string& input) {
  if (!output.empty() && same_output_file(output, input))
    throw std::runtime_error(output + ": is the input '" + input + "'; writing it would destroy it");
}

// Each of `paths` (empty: not asked for) as above, and no two of them one file.
inline void require_output_files(std::initializer_list<const std::string*> paths) {
  for (const std::string* path : paths) require_output_dir(*path);
  for (auto a = paths.begin(); a != paths.end(); ++a)
    for (auto b = a + 1; b != paths.end(); ++b)
      if (!(*a)->empty() && !(*b)->empty() && same_output_file(**a, **b))
        throw std::runtime_error(**a + " and " + **b + ": two outputs to one file");
}

}  // namespace htx
