#include "core/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/error.h"

namespace maquette {
namespace {

[[noreturn]] void fail(const std::string& path, int err) {
  throw Error("cannot write " + path + ": " + std::strerror(err));
}

// Flushes a file's data to the disk; 0 or the errno of the failure.
int sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int err = ::fsync(fd) == 0 ? 0 : errno;
  return ::close(fd) == 0 ? err : (err ? err : errno);
}

}  // namespace

OutputFile::OutputFile(std::string path, std::vector<std::string> sidecars)
    : path_(std::move(path)), sidecars_(std::move(sidecars)) {
  static std::atomic<int> serial = 0;
  temp_ = path_ + ".part." + std::to_string(::getpid()) + "." + std::to_string(serial++);
}

OutputFile::~OutputFile() {
  if (committed_) return;
  ::unlink(temp_.c_str());
  for (const std::string& s : sidecars_) ::unlink((temp_ + s).c_str());
}

void OutputFile::commit(bool sync) {
  if (const int err = sync ? sync_file(temp_) : 0; err != 0) fail(path_, err);
  for (const std::string& s : sidecars_) {
    ::unlink((path_ + s).c_str());  // a stale one would describe another file
    if (::access((temp_ + s).c_str(), F_OK) != 0) continue;
    if (const int err = sync ? sync_file(temp_ + s) : 0; err != 0) fail(path_ + s, err);
    if (::rename((temp_ + s).c_str(), (path_ + s).c_str()) != 0) fail(path_ + s, errno);
  }
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail(path_, errno);
  committed_ = true;
}

void write_file_whole(const std::string& path, std::span<const char> bytes) {
  OutputFile out(path);
  const int fd = ::open(out.temp_path().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, errno);
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      fail(path, err);
    }
    done += size_t(n);
  }
  if (::close(fd) != 0) fail(path, errno);
  out.commit(false);
}

}  // namespace maquette
