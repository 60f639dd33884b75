// glTF model files written for the tests of gltf/gltf_model.h: a textured quad drawn by a
// hierarchy of nodes, as a .gltf with its buffer and image beside it, with data URIs, or as a GLB.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::test {

struct ModelFile {
  nlohmann::json gltf;  // its buffer's uri and image's uri are left for the writer to set
  std::string bin;      // the buffer
  std::string image;    // a PNG
};

// The glTF of a model drawing one mesh of one primitive with one material (`material`, its base
// colour texture image 0, whose uri or bufferView is left for the writer): POSITION, NORMAL,
// TEXCOORD_0 and the indices are accessors 0 to 3 (`accessors`), on the bufferViews `views` of
// buffer 0 (`buffer_bytes` long); scene 0 draws `roots` of `nodes`.
nlohmann::json one_primitive_gltf(const nlohmann::json& nodes, const nlohmann::json& roots,
                                  const nlohmann::json& material, const nlohmann::json& accessors,
                                  const nlohmann::json& views, size_t buffer_bytes);

// A unit quad in glTF's xz plane facing +y (positions at a 16-byte stride, normals, uvs as
// normalized unsigned shorts, unsigned byte indices), drawn by node 1 (rotated 90 degrees about
// y, scaled by 2) child of node 0 (translated by (10, 20, 30)), and by node 2 (mirrored in x).
ModelFile quad_model();

// Writes `m` as DIR/NAME.gltf with NAME.bin and NAME.png beside it; returns the .gltf's path.
std::string write_external(const ModelFile& m, const std::string& dir, const std::string& name);
// Writes `m` as one .gltf with the buffer and image in data URIs.
std::string write_data_uris(const ModelFile& m, const std::string& dir, const std::string& name);
// Writes `m` as a GLB (the buffer in its BIN chunk, the image in a bufferView).
std::string write_glb(const ModelFile& m, const std::string& dir, const std::string& name);

void write_bytes(const std::string& path, const std::string& bytes);

}  // namespace maquette::test
