// Output files written whole or not at all: written under a temporary name next to the final one,
// every write and the close checked, and renamed into place only when all went well. A failure
// (a full disk, a read-only directory) leaves nothing behind, and an older file at the final
// path stays as it was.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace maquette {

class OutputFile {
 public:
  // `sidecars`: suffixes of files a writer may add next to the temporary one (".aux.xml"),
  // renamed with it (a stale sidecar of the final file is removed) or removed with it.
  explicit OutputFile(std::string path, std::vector<std::string> sidecars = {});
  ~OutputFile();  // removes the temporary file and its sidecars unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Where the writer writes: PATH.part.PID.N (the same directory, so the rename is atomic).
  const std::string& temp_path() const { return temp_; }
  const std::string& path() const { return path_; }
  // Syncs the temporary file and its sidecars to the disk (a delayed write error shows here;
  // `sync` false: for a writer that checked every write and its close itself, and writes many
  // small files), then renames them into place. Throws maquette::Error naming the final path and
  // the reason.
  void commit(bool sync = true);

 private:
  std::string path_, temp_;
  std::vector<std::string> sidecars_;
  bool committed_ = false;
};

// Writes `bytes` (a string, a vector of char) to `path` through an OutputFile. Throws
// maquette::Error naming the path and the reason (e.g. "No space left on device").
void write_file_whole(const std::string& path, std::span<const char> bytes);

}  // namespace maquette
