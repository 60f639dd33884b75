#include "core/file_access.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace maquette {

std::optional<std::string> file_access_problem(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return errno == ENOENT   ? "no such file"
           : errno == EACCES ? "permission denied"
                             : std::strerror(errno);
  if (S_ISDIR(st.st_mode)) return "a directory, not a file";
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno == EACCES ? "permission denied" : std::strerror(errno);
  ::close(fd);
  return std::nullopt;
}

}  // namespace maquette
