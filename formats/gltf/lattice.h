// The quantization lattice of a level: Draco's explicit quantization with a power-of-two step
// shared by all cells of the level and a per-cell origin that is a multiple of the step. Then a
// lattice point is a float Draco quantizes and dequantizes exactly, whatever the origin, so a
// vertex shared by two cells decodes to identical coordinates in both.
#pragma once

#include <array>
#include <vector>

namespace maquette {

struct Lattice {
  double step = 1;
  int bits = 14;

  // The step for meshes whose extent (largest side of their bounding box) is at most
  // `max_extent`, with room for flooring the origin onto the lattice.
  static Lattice for_extent(double max_extent, int bits);

  // The mesh's quantization origin: its minimum corner floored onto the lattice.
  std::array<float, 3> origin(const std::vector<float>& positions) const;
  // Draco's explicit range: (2^bits - 1) steps.
  float range() const;
  // Moves every position to its nearest lattice point (what Draco will decode).
  void snap(std::vector<float>& positions, const std::array<float, 3>& origin) const;
};

// The largest side of the bounding box of 3-component positions.
double extent(const std::vector<float>& positions);

}  // namespace maquette
