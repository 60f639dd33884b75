// A building as an LoD1 solid: its footprint extruded from z = 0 to z = height in the footprint's
// plane (x east, y north, z up, metres), and the checks val3dity makes of a solid.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "footprint.h"

namespace maquette::structures {

// A planar face of the solid: triangles [first, first + count) of Solid::indices.
struct SolidFace {
  uint32_t first = 0, count = 0;
};

struct Solid {
  // The footprint's points (ring after ring) at z = 0, then the same at z = height.
  std::vector<double> positions;  // x, y, z per vertex
  std::vector<uint32_t> indices;  // triangles, counter-clockwise seen from outside
  std::vector<SolidFace> faces;   // the floor, the roof, then one wall per footprint edge
};

// The prism of `footprint` (from make_footprint) and `height` (> 0): a floor and a flat roof
// triangulated with the footprint's holes (roof_triangulation.h), a wall of two triangles per
// edge; courtyards give inner walls. Vertices are shared between faces (closed by index).
Solid extrude(const Footprint& footprint, double height);

// val3dity's checks of a shell: closed and consistently oriented (every edge used exactly once
// in each direction), outward (positive volume), no sliver triangle (area below kSliverRatio
// times its longest edge squared: scale-free, so a thin wall of a tall building passes where a
// roof triangle a few micrometres thin does not), each face planar within kPlanarityM, and a
// volume within 1e-9 relative of `expected_volume`. Self-intersection is not
// tested here: an extrusion of a valid footprint (make_footprint) has none. Returns what fails
// first, empty when valid.
inline constexpr double kPlanarityM = 0.01;
// A triangle of area below this times its longest edge squared (its height below 2e-7 of that
// edge) has a shape, and a normal, lost in the float32 rounding of the content's positions
// (2^-24 relative, content/content.h).
inline constexpr double kSliverRatio = 1e-7;
std::string solid_problem(const Solid& solid, double expected_volume);

// The volume of a closed, consistently oriented mesh (divergence theorem).
double mesh_volume(const std::vector<double>& positions, const std::vector<uint32_t>& indices);

}  // namespace maquette::structures
