// A GLB's chunks (glTF 2.0 binary: a 12-byte header "glTF", version, length; a JSON chunk; an
// optional BIN chunk), split without decoding anything else. In libmaquette, so that the store
// (model layers' statistics) and formats/gltf (exports merging stored GLBs, gltf/glb_merge.h)
// read GLBs the same way; it needs nothing of Draco.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace maquette {

// A GLB's two chunks (the BIN chunk empty when it has none).
struct GlbChunks {
  nlohmann::json gltf;
  std::string_view bin;  // a view of the GLB given to split_glb
};

// Throws maquette::Error naming `where` when `glb` is not a GLB (header, chunk types and lengths,
// a JSON chunk that does not parse to an object).
GlbChunks split_glb(std::string_view glb, const std::string& where);

}  // namespace maquette
