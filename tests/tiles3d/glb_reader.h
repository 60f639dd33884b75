// Reads the GLB files the exports write: the JSON chunk, and every Draco primitive decoded with
// draco::Decoder, checked against its accessors (counts, attribute set, position bounds).
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace maquette::test {

struct DecodedPrimitive {
  // Decoded, then placed by the mesh's node and its parents (matrix or translation): the
  // export's frame (glTF axes).
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<float, 3>> normals;   // decoded, one per position (if any)
  std::vector<std::array<uint32_t, 3>> faces;  // into positions
  size_t index_count = 0;
};

struct Glb {
  nlohmann::json json;
  std::vector<char> bin;
  std::vector<DecodedPrimitive> primitives;  // the Draco-compressed ones

  // A node's translation (0 when it has none).
  std::array<double, 3> translation(int node = 0) const;
  // A point of a node's frame in the scene's: through the node's and its parents' matrix or
  // translation (the transforms the exports write).
  std::array<double, 3> place(int node, const std::array<double, 3>& p) const;
  // The values of a plain float accessor (e.g. instance attributes).
  std::vector<float> floats(int accessor) const;
  // The bytes of image `index` (a PNG or JPEG file).
  std::vector<char> image(int index) const;
};

// Reads and decodes `path`; every mismatch with the accessors is a GoogleTest failure.
Glb read_glb(const std::string& path);

// How many distinct decoded positions of the first primitives of `a` and `b` are identical.
size_t shared_vertices(const Glb& a, const Glb& b);

}  // namespace maquette::test
