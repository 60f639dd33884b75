// Reading glTF 2.0: a GLB or a .gltf (JSON) with its buffers (the GLB's BIN chunk, external files
// beside it, or data URIs), then its primitives' vertices (plain accessors or
// KHR_draco_mesh_compression), materials and images. Shared by the mesh layers' decoder
// (gltf/mesh_glb.h) and the reader of outside models (gltf/gltf_model.h).
//
// Parsed with nlohmann::json and checked here rather than with Draco's own glTF decoder
// (tinygltf): errors then name the file, the glTF field and the value at fault, and a buffer
// declaring more than kMaxGltfBufferBytes is refused before anything is allocated for it.
// Every index and range is checked before it is read: bufferViews within their buffer,
// accessors within their bufferView, vertex indices within the vertices.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "content/content.h"

namespace maquette {

inline constexpr uint64_t kMaxGltfBufferBytes = uint64_t(1) << 30;  // 1 GiB

struct GltfDocument {
  std::string where;               // the file (or blob) named in errors
  std::filesystem::path base_dir;  // of relative URIs; empty: none may be external
  nlohmann::json json;
  std::vector<std::string> buffers;
};

// `bytes`: a GLB (magic "glTF") or glTF JSON. `base_dir`: where relative URIs of buffers and
// images are; empty: none may be external (a store's blob). Throws maquette::Error naming `where`
// and the fault; also on a required extension other than KHR_draco_mesh_compression,
// KHR_mesh_quantization and EXT_texture_webp.
GltfDocument parse_gltf(std::string_view bytes, const std::string& where,
                        const std::filesystem::path& base_dir);

// A triangle primitive's vertices in glTF's frame and axes (y up). Normals, uvs and feature ids
// are empty when absent.
struct GltfPrimitive {
  std::vector<float> positions, normals, uvs;
  std::vector<uint32_t> feature_ids;  // EXT_mesh_features' attribute _FEATURE_ID_0
  std::vector<uint32_t> indices;
  int material = -1;
};

// Throws on a mode other than triangles (4), a missing POSITION, a bad accessor or index.
GltfPrimitive read_primitive(const GltfDocument& doc, int mesh, int primitive);

// The document's materials (PBR metallic-roughness; base-colour images embedded or read from
// their URI). Throws on an image that is missing or of an unknown type.
std::vector<Material> read_materials(const GltfDocument& doc);

// `value` as an index into a glTF array: an unsigned integer below 2^31, else an error naming
// `what` (e.g. "meshes[0].primitives[1].material") and the value.
int gltf_index(const GltfDocument& doc, const nlohmann::json& value, const std::string& what);

// The bytes of bufferView `view` (checked within its buffer).
std::string_view buffer_view(const GltfDocument& doc, int view);

}  // namespace maquette
