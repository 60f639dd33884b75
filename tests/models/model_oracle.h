// The models of tests/models: a textured box written as glTF (y up), and the oracle of what the
// store should hold for a .gltf file, read from the file with this test's own parsing (not
// formats/gltf's).
#pragma once

#include <array>
#include <string>

#include "content/content.h"
#include "model_files.h"

namespace maquette::test {

// A box 2 m east, 1 m north, 3 m up whose base is 0.5 m above its origin, as a glTF model in
// glTF's axes (x, y, z) = (east, up, -north): float positions (with min and max), normals and
// uvs, unsigned short indices, one material of base colour `colour`, roughness 0.75, metallic
// 0.25 and a 16 x 16 PNG texture.
ModelFile box_model(const std::array<float, 4>& colour);

// The single primitive of the .gltf at `path` (accessors of float VEC3 positions and normals,
// float VEC2 uvs, unsigned short indices; its buffer a file beside it), read from the bytes of
// its accessors, in the content's axes (x east, y north, z up) and moved up or down so that its
// lowest vertex is at z = 0: what `ingest --as model` should store.
MeshObject stored_object_oracle(const std::string& path);

}  // namespace maquette::test
