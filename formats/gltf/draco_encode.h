// Draco compression of a terrain mesh: positions on the level's lattice (explicit quantization),
// normals and texture coordinates quantized to the given bits.
#pragma once

#include <vector>

#include "gltf/lattice.h"
#include "gltf/terrain_mesh.h"

namespace maquette {

struct QuantizationBits {
  int position = 14;
  int texcoord = 10;
  int normal = 10;
};

struct DracoPrimitive {
  std::vector<char> data;  // the Draco bitstream
  // Draco attribute ids (KHR_draco_mesh_compression "attributes").
  int position_id = -1, normal_id = -1, texcoord_id = -1;
};

// Encodes `mesh` (already rebased onto `lattice`: Lattice::rebase).
DracoPrimitive encode_draco(const TerrainMesh& mesh, const Lattice& lattice,
                            const QuantizationBits& bits);

}  // namespace maquette
