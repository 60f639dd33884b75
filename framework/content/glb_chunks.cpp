#include "content/glb_chunks.h"

#include "content/little_endian.h"
#include "core/error.h"

namespace maquette {

GlbChunks split_glb(std::string_view glb, const std::string& where) {
  auto fail = [&](const std::string& what) { return Error(where + ": " + what); };
  auto u32 = [&](size_t at) { return le::get<uint32_t>(glb.data() + at); };
  if (glb.size() < 20 || u32(0) != 0x46546C67 || u32(8) != glb.size())
    throw fail("not a GLB (its magic or length)");
  const size_t json_len = u32(12);
  if (u32(16) != 0x4E4F534A || json_len > glb.size() - 20)
    throw fail("no JSON chunk of its stated length");
  GlbChunks parts;
  parts.gltf = nlohmann::json::parse(glb.substr(20, json_len), nullptr, false);
  if (!parts.gltf.is_object()) throw fail("its JSON chunk is not a JSON object");
  const size_t at = 20 + json_len;
  if (at < glb.size()) {
    if (glb.size() - at < 8 || u32(at + 4) != 0x004E4942 || u32(at) > glb.size() - at - 8)
      throw fail("no BIN chunk of its stated length");
    parts.bin = glb.substr(at + 8, u32(at));
  }
  return parts;
}

}  // namespace maquette
