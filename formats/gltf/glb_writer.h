// GLB files of meshes: one glTF mesh and node per primitive, Draco-compressed
// (KHR_draco_mesh_compression: attribute accessors without bufferViews, as the extension
// specifies) or plain, each textured with its embedded image (or of one colour), optionally
// drawn once per instance (EXT_mesh_gpu_instancing). Normals and texture coordinates are
// optional (left out when empty). A mesh's offset is its node's translation.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "content/content.h"
#include "gltf/draco_encode.h"
#include "gltf/terrain_mesh.h"
#include "gltf/texture_image.h"

namespace maquette {

// Per-instance transforms of a node (EXT_mesh_gpu_instancing), in the node's frame.
struct InstanceTransforms {
  std::vector<float> translation;  // 3 per instance
  std::vector<float> rotation;     // unit quaternions (x, y, z, w)
  std::vector<float> scale;        // 3 per instance
  std::vector<uint8_t> colour;     // RGBA8 per instance (linear, multiplies), or empty: _COLOR_0
};

struct GlbPrimitive {
  const TerrainMesh* mesh = nullptr;
  const DracoPrimitive* draco = nullptr;  // nullptr: plain vertex buffers
  const EncodedImage* image = nullptr;    // nullptr: untextured
  std::string name;
  std::array<double, 3> color{0.6, 0.6, 0.6};  // without an image
  // A content material (its factors and image) instead of `image` and `color`; primitives given
  // the same one share it, so its image is written once.
  const Material* material = nullptr;
  const InstanceTransforms* instances = nullptr;  // primitives given the same one share it
};

// The binary chunk, bufferViews and accessors of a GLB being built, and its framing.
class GlbBuffer {
 public:
  // A bufferView of a copy of `size` bytes, at an offset that is a multiple of `alignment` (4;
  // 8 for 64-bit columns of EXT_structural_metadata).
  int view(const void* data, size_t size, int target = 0, size_t alignment = 4);
  int accessor(nlohmann::json accessor);
  // The GLB bytes: `gltf` with the accessors, bufferViews and buffer added (none when empty),
  // then the BIN chunk (left out when empty).
  std::vector<char> finish(nlohmann::json gltf);

 private:
  std::vector<char> bin_;
  nlohmann::json views_ = nlohmann::json::array(), accessors_ = nlohmann::json::array();
};

// `m` as glTF's material: PBR metallic-roughness factors (those other than glTF's default, 1),
// name, doubleSided, and its image (if
// any) appended to `images` in a bufferView of `buffer`, drawn through a texture appended to
// `textures` with sampler `sampler`. A WebP image is the texture's source through
// EXT_texture_webp (glTF's core has JPEG and PNG), which the caller declares.
nlohmann::json content_material(const Material& m, GlbBuffer& buffer, nlohmann::json& images,
                                nlohmann::json& textures, int sampler);
// The sampler of content textures: linear, mipmapped, repeating (glTF's default wrap).
nlohmann::json content_sampler();

// The GLB bytes; `extras` goes to the asset's extras (e.g. the frame's origin).
std::vector<char> make_glb(const std::vector<GlbPrimitive>& primitives,
                           const nlohmann::json& extras = nullptr);

// A GLB of `gltf` (its JSON chunk, padded with spaces) and `bin` (its BIN chunk, padded with zeros;
// left out when empty). `gltf` must already declare the buffer's byteLength.
std::vector<char> glb_file(const nlohmann::json& gltf, std::string_view bin);

void write_file(const std::string& path, const std::vector<char>& bytes);

}  // namespace maquette
