// A GLB holding only its JSON chunk, for tests of what reads a GLB's JSON without its buffers.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace maquette::test {

// glTF 2.0 binary: the header ("glTF", version 2, length), then the JSON chunk (length, "JSON",
// the text padded to 4 bytes with spaces as the format requires).
inline std::string json_glb(const nlohmann::json& gltf) {
  std::string text = gltf.dump();
  while (text.size() % 4) text.push_back(' ');
  std::string glb = "glTF";
  const auto u32 = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  u32(2);
  u32(uint32_t(12 + 8 + text.size()));
  u32(uint32_t(text.size()));
  return glb + "JSON" + text;
}

}  // namespace maquette::test
