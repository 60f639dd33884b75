// The quantization lattice of a level: Draco's explicit quantization with a power-of-two step
// shared by all cells of the level. Positions are snapped to multiples of the step in the export's
// frame, then measured from the mesh's minimum corner (a lattice point too), which becomes the
// mesh's offset: every position is then a small multiple of the step, a float Draco quantizes and
// dequantizes exactly, and a vertex shared by two cells decodes to identical coordinates in both
// (offset + position, in double) wherever the cells lie.
#pragma once

#include <vector>

#include "gltf/terrain_mesh.h"

namespace maquette {

struct Lattice {
  double step = 1;
  int bits = 14;

  // The step for meshes whose extent (largest side of their bounding box) is at most
  // `max_extent`, with room for snapping onto the lattice.
  static Lattice for_extent(double max_extent, int bits);

  // Draco's explicit range, from 0 (the mesh's offset): (2^bits - 1) steps.
  float range() const;
  // Moves every vertex of `mesh` (positions relative to its offset) to its nearest lattice point
  // and sets the offset to their minimum corner: positions are then 0 .. range().
  void rebase(TerrainMesh& mesh) const;
};

// The largest side of the bounding box of 3-component positions.
double extent(const std::vector<double>& positions);

}  // namespace maquette
