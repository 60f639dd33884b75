// Distances in metres on the WGS84 ellipsoid between a point or a cell and a geometry
// (core/geometry.h), horizontal (Z is ignored): 0 when they meet (a point or a cell centre inside
// a polygon, a vertex inside the cell, crossing edges). Used to deliver a features layer's
// features to the cells they come near (runtime: InputSpec::reach_m), and by operators.
//
// How: edges are straight in lon/lat, as in GeoJSON and polygon_contains (core/polygon_set.h);
// they are cut into pieces of at most kPieceDegrees, each taken as the straight 3D segment
// between the ECEF positions of its ends, and the distance is the shortest between segments.
// A cell's outline is its boundary (Grid::boundary) with points at most kOutlineSpacingM apart
// (at most 1024 an edge, so cells coarser than level 5 have sparser points).
//
// Error: the chord of a geodesic of length d is shorter by about d^3 / (24 R^2) (R = 6371 km):
// 0.1 mm at 5 km, 1 mm at 10 km, 8 mm at 20 km, 1 m at 100 km; a piece of an edge runs within
// about 0.6 cm * tan(latitude) of its straight chord (pieces of 0.005 degrees), as do the outline's
// sides. So below 1 cm for distances up to 20 km under 45 degrees of latitude, below 2 cm at 60
// degrees. Polygons must not cross the antimeridian (polygon_contains).
#pragma once

#include <array>
#include <vector>

#include "core/cell_id.h"
#include "core/ecef.h"
#include "core/geometry.h"
#include "core/grid.h"

namespace maquette {

inline constexpr double kPieceDegrees = 0.005;
inline constexpr double kOutlineSpacingM = 500;

// The distance from `p` to `g` (0 inside one of its polygons).
double distance_m(LonLat p, const Geometry& g);

// A geometry's edges as ECEF pieces, with a sphere holding them and the surface inside its
// polygons, computed once for its distances to many cells.
class GeometryPieces {
 public:
  explicit GeometryPieces(const Geometry& g);  // `g` must outlive this

  const Geometry& geometry() const { return *geometry_; }
  const std::vector<std::array<Vec3, 2>>& segments() const { return segments_; }
  const Vec3& centre() const { return centre_; }  // ECEF, metres
  double radius_m() const { return radius_; }

 private:
  const Geometry* geometry_;
  std::vector<std::array<Vec3, 2>> segments_;
  Vec3 centre_{};
  double radius_ = 0;
};

// A cell's outline, computed once for the distances of many geometries to the cell.
class CellOutline {
 public:
  CellOutline(const Grid& grid, CellId cell);

  // The distance from the cell to the geometry: 0 when one of its vertices lies in the cell, the
  // cell's centre in one of its polygons, or edges cross.
  double distance_m(const GeometryPieces& g) const;
  // A sphere holding the outline (ECEF, metres).
  const Vec3& centre() const { return centre_; }
  double radius_m() const { return radius_; }

 private:
  const Grid* grid_;
  CellId cell_;
  LonLat centre_lonlat_;
  Vec3 centre_{};
  double radius_ = 0;
  std::vector<std::array<Vec3, 2>> sides_;  // ECEF segments of the outline
};

// The gap between two spheres (negative when they overlap): two shapes held by spheres more than
// D apart are more than D apart, since a chord is never longer than the surface distance.
double sphere_gap_m(const Vec3& a, double radius_a, const Vec3& b, double radius_b);

}  // namespace maquette
