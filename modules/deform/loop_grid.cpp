#include "loop_grid.h"

#include <stdexcept>
#include <string>

namespace maquette::deform {

GridNodes height_field_nodes(int columns, int rows) {
  if (columns < 1 || rows < 1) {
    throw std::invalid_argument("height field nodes: columns and rows must be >= 1, got " +
                                std::to_string(columns) + " x " + std::to_string(rows));
  }
  GridNodes nodes;
  nodes.reserve(static_cast<std::size_t>(columns) * rows);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) nodes.push_back({c, r});
  }
  return nodes;
}

GridNodes finer_nodes(const GridNodes& coarse,
                      std::span<const std::array<int, 2>> new_vertex_ends) {
  GridNodes fine;
  fine.reserve(coarse.size() + new_vertex_ends.size());
  for (const auto& [c, r] : coarse) fine.push_back({2 * c, 2 * r});
  for (const auto& [a, b] : new_vertex_ends) {
    const auto& p = coarse.at(static_cast<std::size_t>(a));
    const auto& q = coarse.at(static_cast<std::size_t>(b));
    fine.push_back({p[0] + q[0], p[1] + q[1]});
  }
  return fine;
}

}  // namespace maquette::deform
