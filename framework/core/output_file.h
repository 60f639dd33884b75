// Output files written whole or not at all: written under a temporary name next to the final one,
// every write and the close checked, and renamed into place only when all went well. A failure
// (a full disk, a read-only directory) leaves nothing behind, and an older file at the final
// path stays as it was.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/error.h"

namespace maquette {

class OutputFile {
 public:
  // `suffixes`: of sidecars a writer may add next to the temporary one (".aux.xml"), renamed
  // with it (a stale sidecar of the final file is removed) or removed with it. Throws
  // maquette::Error when `path` is a directory.
  explicit OutputFile(std::string path, std::vector<std::string> suffixes = {});
  ~OutputFile();  // removes the temporary file and its sidecars unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Where the writer writes: PATH.part.PID.N (the same directory, so the rename is atomic).
  const std::string& temp_path() const { return temp_; }
  const std::string& path() const { return path_; }
  // A sidecar whose name is not the file's plus a suffix (the world file OUT.pgw of OUT.png):
  // returns the temporary name to write it at; committed and removed with the file.
  std::string add_sidecar(const std::string& final_path);
  // Runs `write` (which writes temp_path() and the sidecars' temporary names) and rethrows a
  // maquette::Error it throws naming the files the user gave instead of the temporary ones (GDAL's
  // messages name the file it writes).
  template <class Write>
  void write(Write&& write) {
    try {
      write();
    } catch (const Error& e) {
      throw Error(with_final_names(e.what()));
    }
  }
  // Syncs the temporary file and its sidecars to the disk (a delayed write error shows here;
  // `sync` false: for a writer that checked every write and its close itself, and writes many
  // small files), then renames them into place, the file first (an old file it cannot replace
  // keeps its sidecars), removing the file's stale sidecars: a failure removes those already
  // renamed. Throws maquette::Error naming the final path and the
  // reason.
  void commit(bool sync = true);

 private:
  struct Sidecar {
    std::string path, temp;
  };
  std::string with_final_names(std::string message) const;

  std::string path_, temp_;
  std::vector<Sidecar> sidecars_;
  bool committed_ = false;
};

// Writes `bytes` to `path` as it is (for a temporary name of an OutputFile), checking every
// write and the close. Throws maquette::Error naming the path and the reason.
void write_new_file(const std::string& path, std::span<const char> bytes);
// Writes `bytes` (a string, a vector of char) to `path` through an OutputFile. Throws
// maquette::Error naming the path and the reason (e.g. "No space left on device").
void write_file_whole(const std::string& path, std::span<const char> bytes);

}  // namespace maquette
