// Several GLBs in one, each under a node of its own: how exports ship stored content GLBs (a mesh
// layer's payload, formats/gltf/README.md) without decoding them, placed by a node matrix, and
// how `export glb` puts the terrain and several cells' content into one file.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "content/glb_chunks.h"  // split_glb, which reads each part

namespace maquette {

struct GlbPart {
  std::string_view glb;
  std::array<double, 16> matrix;  // column-major: the part's scene in the merged one
  std::string name;               // of the part's node
};

// One GLB of one scene holding a node per part (named, with its matrix) whose children are the
// part's scene's nodes. Every array of a part (accessors, bufferViews, images, samplers, textures,
// materials, meshes, nodes, EXT_structural_metadata's property tables) is appended after the
// previous parts' and the part's indices into it shifted; the BIN chunks are concatenated (each
// at a multiple of 8 bytes), so one part's bytes are kept as they are (its BIN chunk and its
// objects, with no index shifted, when it is the only part). extensionsUsed and
// extensionsRequired are the union of the parts'; EXT_structural_metadata's schema must be the
// same in every part that has one. `extras` becomes the asset's extras. Parts are GLBs whose one
// buffer is their BIN chunk (as the exports write them). Throws maquette::Error naming `where`
// and the part for a GLB that is not one, malformed glTF JSON, a part of other than one scene,
// sparse accessors or morph targets (which no export writes), or schemas that differ.
std::vector<char> merge_glbs(const std::vector<GlbPart>& parts, const nlohmann::json& extras,
                             const std::string& where);

}  // namespace maquette
