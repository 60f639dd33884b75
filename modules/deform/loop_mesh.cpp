#include "loop_mesh.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace maquette::deform {

TriangleMesh height_field_mesh(const RegularHeightField& field) {
  if (field.columns < 2 || field.rows < 2) {
    throw std::invalid_argument("height field: columns and rows must be >= 2, got " +
                                std::to_string(field.columns) + " x " + std::to_string(field.rows));
  }
  if (!(field.spacing_x > 0.0) || !(field.spacing_y > 0.0)) {
    throw std::invalid_argument("height field: spacing_x and spacing_y must be > 0, got " +
                                std::to_string(field.spacing_x) + ", " +
                                std::to_string(field.spacing_y));
  }
  const auto samples = static_cast<std::size_t>(field.columns) * field.rows;
  if (field.heights.size() != samples) {
    throw std::invalid_argument("height field: heights has " +
                                std::to_string(field.heights.size()) +
                                " values, columns x rows = " + std::to_string(samples));
  }
  TriangleMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(samples), 3);
  for (int r = 0; r < field.rows; ++r) {
    for (int c = 0; c < field.columns; ++c) {
      const int v = r * field.columns + c;
      const double z = field.heights[static_cast<std::size_t>(v)];
      if (!std::isfinite(z)) {
        throw std::invalid_argument("height field: heights[" + std::to_string(v) + "] (column " +
                                    std::to_string(c) + ", row " + std::to_string(r) +
                                    ") is not finite");
      }
      mesh.vertices.row(v) << c * field.spacing_x, -r * field.spacing_y, z;
    }
  }
  mesh.triangles.reserve(2 * static_cast<std::size_t>(field.columns - 1) * (field.rows - 1));
  for (int r = 0; r + 1 < field.rows; ++r) {
    for (int c = 0; c + 1 < field.columns; ++c) {
      const int v00 = r * field.columns + c;
      const int v10 = v00 + 1;
      const int v01 = v00 + field.columns;
      const int v11 = v01 + 1;
      mesh.triangles.push_back({v00, v11, v10});
      mesh.triangles.push_back({v00, v01, v11});
    }
  }
  return mesh;
}

}  // namespace maquette::deform
