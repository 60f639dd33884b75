// Helpers for the store tests: a temporary directory, tiles with known contents, expected
// errors, and SQL run on a store file behind its back.
#pragma once

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <string>

#include "core/error.h"
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

// Expects `f` to throw a maquette::Error whose message contains every one of `parts`.
template <typename F>
void expect_error(F&& f, std::initializer_list<std::string> parts) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one mentioning " << *parts.begin();
  } catch (const Error& e) {
    for (const auto& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "'" << e.what() << "' does not mention '" << part << "'";
  }
}

// Runs SQL on a store file directly, as a foreign program (or a disk fault) would.
inline void raw_sql(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  char* err = nullptr;
  EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err), SQLITE_OK) << (err ? err : "");
  sqlite3_free(err);
  sqlite3_close(db);
}

// The integer the first row of a query gives, read from a store file directly (0 without a row).
inline int64_t raw_int(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &q, nullptr), SQLITE_OK) << sql;
  const int64_t v = sqlite3_step(q) == SQLITE_ROW ? sqlite3_column_int64(q, 0) : 0;
  sqlite3_finalize(q);
  sqlite3_close(db);
  return v;
}

}  // namespace maquette::test
