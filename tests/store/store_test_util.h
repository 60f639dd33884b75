// Helpers for the store tests: a temporary directory and tiles with known contents.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/tile.h"

namespace maquette::test {

// A fresh directory under the system temp dir, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "maquette-store-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

template <typename T>
RawTile raw_tile(int size, int channels, const std::vector<T>& values) {
  RawTile t{dtype_of<T>(), size, channels, std::vector<std::byte>(values.size() * sizeof(T))};
  std::memcpy(t.bytes.data(), values.data(), t.bytes.size());
  return t;
}

template <typename T>
std::vector<T> values_of(const RawTile& t) {
  std::vector<T> v(t.bytes.size() / sizeof(T));
  std::memcpy(v.data(), t.bytes.data(), t.bytes.size());
  return v;
}

// A smooth float32 tile (a sum of sines, like terrain) whose values depend on `seed`.
inline RawTile smooth_tile(int size, float seed = 0) {
  std::vector<float> v(size_t(size) * size_t(size));
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c)
      v[size_t(r) * size + c] = 500.0f + 120.0f * std::sin(0.031f * c + seed) +
                                80.0f * std::cos(0.047f * r - seed) +
                                15.0f * std::sin(0.11f * (c + r) + 2 * seed);
  return raw_tile<float>(size, 1, v);
}

}  // namespace maquette::test
