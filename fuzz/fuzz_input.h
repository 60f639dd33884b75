// What the fuzz targets share: the fuzzer's bytes as text, a scratch file for the parsers that
// read a path, and the split of one input into the two parts of a stored feature.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace maquette::fuzz {

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The path of `name` in a directory of this process's own (made once under TMPDIR, else /tmp).
std::string scratch_path(const std::string& name);
// The file scratch_path(name) holding `bytes`, overwritten by each call with the same name.
std::string scratch_file(const std::string& name, std::string_view bytes);

// A stored feature as one input: its attributes (JSON text), a NUL byte, then its geometry (WKB).
// Without a NUL byte, the attributes are empty and every byte is WKB.
struct FeatureBytes {
  std::string_view attributes;
  std::span<const std::byte> wkb;
};
FeatureBytes split_feature(const uint8_t* data, size_t size);

}  // namespace maquette::fuzz
