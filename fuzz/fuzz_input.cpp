#include "fuzz_input.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace maquette::fuzz {
namespace {

std::string make_scratch_dir() {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern =
      std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/maquette-fuzz-XXXXXX";
  if (mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot make a scratch directory " + pattern);
  return pattern;
}

}  // namespace

std::string scratch_path(const std::string& name) {
  static const std::string dir = make_scratch_dir();
  return dir + "/" + name;
}

std::string scratch_file(const std::string& name, std::string_view bytes) {
  const std::string path = scratch_path(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + path);
  return path;
}

FeatureBytes split_feature(const uint8_t* data, size_t size) {
  const std::string_view all = as_text(data, size);
  const size_t nul = all.find('\0');
  if (nul == std::string_view::npos) return {{}, std::as_bytes(std::span(data, size))};
  return {all.substr(0, nul), std::as_bytes(std::span(data + nul + 1, size - nul - 1))};
}

}  // namespace maquette::fuzz
