// The DEM as a triangulated height field (paper 002 §3.2): samples (col, row) of a width x height
// raster, each square (col, row)-(col + 1, row + 1) split into two triangles along its diagonal
// from (col, row) to (col + 1, row + 1):
//   upper (col, row), (col + 1, row), (col + 1, row + 1) and lower (col, row), (col, row + 1),
//   (col + 1, row + 1).
// Every interior vertex has the six neighbours kNeighbours (valence 6: Loop subdivision's regular
// case). Samples carry their horizontal position in metres (east, north in a local tangent plane),
// so that the cotangent weights see the true shape of rHEALPix's non-square pixels.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace maquette::deform {

struct HeightField {
  int width = 0, height = 0;
  std::vector<double> east, north;  // metres, row-major, width * height
  std::vector<double> z;            // metres, NaN for nodata

  size_t index(int col, int row) const { return size_t(row) * size_t(width) + size_t(col); }
};

// The six neighbours of a vertex (col, row offsets), counter-clockwise in (col, row): consecutive
// pairs (cyclically) with the vertex make its six triangles.
inline constexpr std::array<std::array<int, 2>, 6> kNeighbours{
    {{1, 0}, {1, 1}, {0, 1}, {-1, 0}, {-1, -1}, {0, -1}}};

// A point of the surface as the barycentric combination of its triangle's vertices (Eq. 2), and
// where it is in fractional sample coordinates (col, row), to locate it on finer levels.
struct SurfacePoint {
  std::array<size_t, 3> vertex{};
  std::array<double, 3> weight{};
  std::array<double, 2> sample{};
};

// The triangle holding the point at fractional sample coordinates (col, row) (sample centres at
// integers) and its barycentric coordinates there. Precondition: 0 <= col < width - 1 and
// 0 <= row < height - 1 (the caller checks, to name what lies outside).
SurfacePoint locate(const HeightField& field, double col, double row);

// The surface's height at a located point.
double height_at(const HeightField& field, const SurfacePoint& p);

// The surface's height at fractional sample coordinates (col, row) moved into the field (the
// nearest point of its samples' hull): the linear interpolation of the triangulation.
double height_at_clamped(const HeightField& field, double col, double row);
// The coordinates height_at_clamped locates: col in [0, width - 1), row in [0, height - 1) (below
// the last column and row, so that the triangle is inside the field).
double clamped_col(const HeightField& field, double col);
double clamped_row(const HeightField& field, double row);

// Normalized cotangent weights of the interior vertex (col, row) towards its kNeighbours, from the
// horizontal positions (the height field's domain): (cot a + cot b) / 2 per edge, negative
// cotangents (obtuse angles of strongly sheared pixels) taken as 0 so the weights stay a convex
// combination, divided by their sum. Precondition: 1 <= col <= width - 2, 1 <= row <= height - 2.
std::array<double, 6> cotangent_weights(const HeightField& field, int col, int row);

}  // namespace maquette::deform
