#include "core/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
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

OutputFile::OutputFile(std::string path, std::vector<std::string> suffixes)
    : path_(std::move(path)) {
  // Said before anything is written: the rename at commit() would fail after the work.
  if (struct stat st; ::stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) fail(path_, EISDIR);
  static std::atomic<int> serial = 0;
  temp_ = path_ + ".part." + std::to_string(::getpid()) + "." + std::to_string(serial++);
  for (const std::string& s : suffixes) sidecars_.push_back({path_ + s, temp_ + s});
}

OutputFile::~OutputFile() {
  if (committed_) return;
  ::unlink(temp_.c_str());
  for (const Sidecar& s : sidecars_) ::unlink(s.temp.c_str());
}

std::string OutputFile::add_sidecar(const std::string& final_path) {
  sidecars_.push_back({final_path, final_path + temp_.substr(path_.size())});
  return sidecars_.back().temp;
}

std::string OutputFile::with_final_names(std::string message) const {
  const auto replace = [&message](const std::string& from, const std::string& to) {
    for (size_t at = message.find(from); at != std::string::npos;
         at = message.find(from, at + to.size()))
      message.replace(at, from.size(), to);
  };
  for (const Sidecar& s : sidecars_) replace(s.temp, s.path);
  replace(temp_, path_);
  return message;
}

void OutputFile::commit(bool sync) {
  if (sync) {
    if (const int err = sync_file(temp_); err != 0) fail(path_, err);
    for (const Sidecar& s : sidecars_)
      if (::access(s.temp.c_str(), F_OK) == 0)
        if (const int err = sync_file(s.temp); err != 0) fail(s.path, err);
  }
  std::vector<const std::string*> renamed;
  const auto rename = [&renamed](const std::string& from, const std::string& to) {
    if (::rename(from.c_str(), to.c_str()) == 0) return renamed.push_back(&to);
    const int err = errno;
    for (const std::string* done : renamed) ::unlink(done->c_str());
    fail(to, err);
  };
  // The file first: if it cannot be replaced, the old one keeps its sidecars (an rHEALPix
  // GeoTIFF's CRS is in its .aux.xml).
  rename(temp_, path_);
  for (const Sidecar& s : sidecars_) {
    if (::access(s.temp.c_str(), F_OK) == 0)
      rename(s.temp, s.path);
    else
      ::unlink(s.path.c_str());  // a stale one would describe another file
  }
  committed_ = true;
}

void write_new_file(const std::string& path, std::span<const char> bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
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
}

void write_file_whole(const std::string& path, std::span<const char> bytes) {
  OutputFile out(path);
  out.write([&] { write_new_file(out.temp_path(), bytes); });
  out.commit(false);
}

}  // namespace maquette
