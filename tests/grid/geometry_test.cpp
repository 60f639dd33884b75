// Cell geometry: children tile their parent, centres lie in their cell, and the geodesic area of
// densified boundaries (GeographicLib PolygonArea) equals the exact cell area.
#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/PolygonArea.hpp>
#include <random>

#include "core/error.h"
#include "rhealpix/rhealpix_grid.h"
#include "test_util.h"

namespace maquette {
namespace {

double geodesic_area(const std::vector<LonLat>& ring) {
  GeographicLib::PolygonArea polygon(GeographicLib::Geodesic::WGS84());
  for (size_t i = 0; i + 1 < ring.size(); ++i) polygon.AddPoint(ring[i].lat, ring[i].lon);
  double perimeter = 0, area = 0;
  polygon.Compute(false, true, perimeter, area);
  return area;
}

std::vector<CellId> sample_cells() {
  std::vector<CellId> out;
  std::mt19937 rng(7);
  for (int level = 0; level <= 12; ++level) {
    for (int face = 0; face < 6; ++face) {
      for (int i = 0; i < 2; ++i) {
        std::uniform_int_distribution<uint32_t> index(0, (1U << level) - 1);
        out.push_back(CellId::FromFaceColRow(face, level, index(rng), index(rng)));
      }
    }
  }
  // Around and at the poles, on the antimeridian ray of the polar faces, on the face edges.
  for (const char* t :
       {"N", "S", "N0", "N3", "S1", "S2", "N3000", "N0333", "S12222", "N21", "N21212", "S01",
        "N300000000000", "S033333333333", "O0", "R1", "O02020", "R13131"}) {
    out.push_back(*CellId::FromText(t));
  }
  return out;
}

TEST(Geometry, ChildrenTileTheParent) {
  const Grid& grid = default_grid();
  for (const CellId cell : sample_cells()) {
    const PlaneSquare p = grid.plane_square(cell);
    for (int d = 0; d < 4; ++d) {
      const PlaneSquare c = grid.plane_square(cell.child(d));
      EXPECT_DOUBLE_EQ(c.side, p.side / 2);
      EXPECT_NEAR(c.x_min, p.x_min + (d & 1) * c.side, 1e-6);
      EXPECT_NEAR(c.y_max, p.y_max - (d >> 1) * c.side, 1e-6);
    }
  }
}

// Independent of plane_square's arithmetic: points of the parent's square, taken to the
// ellipsoid (inverse) and back to a cell (forward), land in the child whose quadrant holds them.
TEST(Geometry, PointsOfTheParentLandInThePredictedChild) {
  const Grid& grid = default_grid();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.01, 0.99);
  for (const CellId cell : sample_cells()) {
    if (cell.level() >= CellId::kMaxLevel) continue;
    const PlaneSquare p = grid.plane_square(cell);
    for (int k = 0; k < 8; ++k) {
      const double u = unit(rng), v = unit(rng);
      if (std::abs(u - 0.5) < 0.02 || std::abs(v - 0.5) < 0.02) continue;  // off the midlines
      const LonLat ll = grid.inverse({p.x_min + u * p.side, p.y_max - v * p.side});
      const int digit = 2 * int(v >= 0.5) + int(u >= 0.5);
      EXPECT_EQ(grid.cell_from_point(ll, cell.level() + 1), cell.child(digit))
          << cell.ToText() << " u=" << u << " v=" << v;
    }
  }
}

TEST(Geometry, CentreLiesInItsCell) {
  const Grid& grid = default_grid();
  for (const CellId cell : sample_cells()) {
    EXPECT_EQ(grid.cell_from_point(grid.centre(cell), cell.level()), cell) << cell.ToText();
  }
}

TEST(Geometry, BoundaryAreaIsExact) {
  const Grid& grid = default_grid();
  for (const CellId cell : sample_cells()) {
    // Geodesic chords cut the curved cell edges: the relative error falls with the level and
    // with the square of the points per edge; polar cells at levels 1-3 need the most.
    const int points = cell.level() == 0 ? 1024 : 512;
    const auto ring = grid.boundary(cell, points);
    EXPECT_EQ(ring.front().lon, ring.back().lon);
    EXPECT_EQ(ring.front().lat, ring.back().lat);
    // Longitudes are continuous, except along a pole.
    for (size_t i = 1; i < ring.size(); ++i) {
      if (std::abs(ring[i].lat) == 90 && ring[i].lat == ring[i - 1].lat) continue;
      EXPECT_LE(std::abs(ring[i].lon - ring[i - 1].lon), 180) << cell.ToText();
    }
    const double area = grid.area(cell.level());
    EXPECT_NEAR(geodesic_area(ring), area, 1e-6 * area) << cell.ToText();
  }
  EXPECT_THROW(grid.boundary(*CellId::FromText("Q"), 0), Error);
}

TEST(Geometry, AntimeridianRingIsContinuous) {
  const Grid& grid = default_grid();
  // N21 straddles the ray of longitude 180 of the north face.
  const auto ring = grid.boundary(*CellId::FromText("N21"), 16);
  double min = 1e9, max = -1e9;
  for (const LonLat p : ring) min = std::min(min, p.lon), max = std::max(max, p.lon);
  EXPECT_LT(max - min, 180);
  EXPECT_TRUE(min < -180 || max > 180);
}

}  // namespace
}  // namespace maquette
