// structures.bridge's deck (paper 002 §7, Fig. 16) as a solid: the slab between a bridge's two
// edge strokes, its top through the edges, its floor a thickness below.
#pragma once

#include <array>
#include <vector>

#include "building_solid.h"

namespace maquette::structures {

// A point of an edge's top in the deck's frame (x east, y north, z up, metres).
using DeckPoint = std::array<double, 3>;

// Heights along an edge of horizontal points (x, y; at least 2 distinct): linear in the arc length
// from `start` at its first point to `end` at its last (the deck's slant along its length).
std::vector<double> edge_profile(const std::vector<PlanePoint2>& edge, double start, double end);

// The deck between two edges (open polylines of at least 2 points, each given from the same end
// of the bridge to the other): its outline is the first edge, then the second reversed; its top
// passes through every edge point, triangulated between the edges (roof_triangulation.h) with
// each triangle a face of its own (the top is a plane only when the four ends are); its floor is
// the top moved `thickness` (> 0) straight down; a wall of two triangles (a parallelogram) per
// outline edge. The vertices follow building_solid.h's Solid: the outline's points at the floor,
// then at the top; the first is the first edge's first point at the floor. A vertical shear of the
// outline's prism: checked with solid_problem (closed, outward, planar faces, volume = outline
// area x thickness to 1e-9). Throws InvalidFootprint naming what fails: the edges crossing or
// touching (with the point), an outline of no area, an invalid solid.
Solid deck_solid(const std::vector<DeckPoint>& first_edge,
                 const std::vector<DeckPoint>& second_edge, double thickness);

}  // namespace maquette::structures
