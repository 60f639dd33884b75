// GLB files of terrain meshes: one glTF mesh and node per primitive, Draco-compressed
// (KHR_draco_mesh_compression: attribute accessors without bufferViews, as the extension
// specifies) or plain, each textured with its embedded image (or untextured grey).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gltf/draco_encode.h"
#include "gltf/terrain_mesh.h"
#include "gltf/texture_image.h"

namespace maquette {

struct GlbPrimitive {
  const TerrainMesh* mesh = nullptr;
  const DracoPrimitive* draco = nullptr;  // nullptr: plain vertex buffers
  const EncodedImage* image = nullptr;    // nullptr: untextured
  std::string name;
};

// The GLB bytes; `extras` goes to the asset's extras (e.g. the frame's origin).
std::vector<char> make_glb(const std::vector<GlbPrimitive>& primitives,
                           const nlohmann::json& extras = nullptr);

void write_file(const std::string& path, const std::vector<char>& bytes);

}  // namespace maquette
