// A building as a solid: its footprint's walls from z = 0 up to its roof (roof_surface.h: flat,
// LoD1, or pitched, LoD2) in the footprint's plane (x east, y north, z up, metres), and the
// checks val3dity makes of a solid.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "footprint.h"
#include "roof_surface.h"

namespace maquette::structures {

// A planar face of the solid: triangles [first, first + count) of Solid::indices.
struct SolidFace {
  uint32_t first = 0, count = 0;
};

struct Solid {
  // The roof surface's points (the footprint's, ring after ring, then those added on creases) at
  // z = 0, then the same at the roof's height.
  std::vector<double> positions;  // x, y, z per vertex
  std::vector<uint32_t> indices;  // triangles, counter-clockwise seen from outside
  // The floor, one face per roof plane that shows, then one wall per edge of the roof's outline
  // (the footprint's edges, split where creases cross them).
  std::vector<SolidFace> faces;
};

// The solid under `roof` (from roof_surface): a floor of the roof's triangles at z = 0, the
// roof, a wall of two triangles per outline edge from the floor up to the roof (a gable wall in
// two, meeting under the ridge); courtyards give inner walls. Vertices shared between faces
// (closed by index). Its volume is roof.volume().
Solid extrude(const RoofSurface& roof);

// The prism of `footprint` (from make_footprint) and `height` (> 0): a flat roof at the height.
Solid extrude(const Footprint& footprint, double height);

// val3dity's checks of a shell: closed and consistently oriented (every edge used exactly once
// in each direction), outward (positive volume), no sliver triangle (area below kSliverRatio
// times its longest edge squared: scale-free, so a thin wall of a tall building passes where a
// roof triangle a few micrometres thin does not), each face planar within kPlanarityM, and a
// volume within 1e-9 relative of `expected_volume` (a closed form: area x height, or
// RoofSurface::volume). Self-intersection is not tested here: the solid under a roof surface over
// a valid footprint (make_footprint), above z = 0 everywhere, has none. Returns what fails first,
// empty when valid.
inline constexpr double kPlanarityM = 0.01;
// A triangle of area below this times its longest edge squared (its height below 2e-7 of that
// edge) has a shape, and a normal, lost in the float32 rounding of the content's positions
// (2^-24 relative, content/content.h).
inline constexpr double kSliverRatio = 1e-7;
std::string solid_problem(const Solid& solid, double expected_volume);

// The volume of a closed, consistently oriented mesh (divergence theorem).
double mesh_volume(const std::vector<double>& positions, const std::vector<uint32_t>& indices);

}  // namespace maquette::structures
