// Where the vertices of a subdivided height field are on the finer grids: at level k the grid has
// 2^k (columns - 1) + 1 by 2^k (rows - 1) + 1 nodes, (column, row) at x = column * spacing_x / 2^k,
// y = -row * spacing_y / 2^k. Loop subdivision keeps inner vertices there (its masks reproduce
// linear functions) but pulls those near the height field's corners inwards (the border curve
// turns there), so the node of a vertex comes from the subdivision's topology, not its position:
// a height map per level is then z of the vertices at their nodes.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace maquette::deform {

using GridNodes = std::vector<std::array<int, 2>>;

// Level 0: vertex r * columns + c (height_field_mesh) at node (c, r).
// Precondition: columns >= 1, rows >= 1 (std::invalid_argument otherwise).
GridNodes height_field_nodes(int columns, int rows);

// The nodes one level finer: a kept vertex at twice its node, a new vertex (coarse.size() + i)
// between the nodes of its edge's ends (new_vertex_ends of LoopLevel or AdaptiveLoop).
// Precondition: the ends index `coarse` (std::out_of_range otherwise).
GridNodes finer_nodes(const GridNodes& coarse, std::span<const std::array<int, 2>> new_vertex_ends);

}  // namespace maquette::deform
