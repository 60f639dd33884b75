// Triangle meshes for Loop subdivision (paper 002, §3.2): the DEM as a triangulated height field.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

namespace maquette::deform {

// Vertices (one row each: x, y, z in metres of a local metric frame) and counter-clockwise
// triangles (seen from +z for a height field) indexing them.
struct TriangleMesh {
  Eigen::MatrixX3d vertices;
  std::vector<std::array<int, 3>> triangles;
};

// A level of subdivision as a linear map, fine vertices = matrix * coarse vertices; stored by
// rows, since a constraint on the fine surface combines rows (paper 002, Eq. 4).
using SubdivisionMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Heights sampled on a regular grid in raster order: sample (column c, row r) is at
// x = c * spacing_x, y = -r * spacing_y, z = heights[r * columns + c]. Rows go towards -y (south
// on a north-up raster, row 0 at the north), as the operator's HeightField (height_field.h).
struct RegularHeightField {
  int columns = 0;
  int rows = 0;
  double spacing_x = 0.0;
  double spacing_y = 0.0;
  std::vector<double> heights;
};

// The height field as a triangle mesh: vertex r * columns + c per sample; each square of samples
// (c, r)-(c+1, r+1) split along its diagonal from (c, r) to (c+1, r+1) (the operator's rule,
// height_field.h) into the triangles {(c, r), (c+1, r+1), (c+1, r)} and {(c, r), (c, r+1),
// (c+1, r+1)}, counter-clockwise seen from +z, square by square in row-major
// order (triangle 2 * (r * (columns - 1) + c) and the next one). The diagonal is the same in every
// square, so the mesh has valence 6 inside and the subdivision treats the grid the same everywhere.
// Preconditions: columns >= 2, rows >= 2, spacings > 0, heights.size() == columns * rows, finite
// heights (std::invalid_argument naming the field otherwise).
TriangleMesh height_field_mesh(const RegularHeightField& field);

}  // namespace maquette::deform
