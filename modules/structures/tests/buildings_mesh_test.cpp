// building_mesh on hand-made features: a MultiPolygon (a courtyard with an island building in it,
// and a separate part) gives one valid shell per part by CGAL, of the tagged height, on the
// lowest DEM sample; a gabled roof and a dome (built flat, with a warning); footprints across an
// edge of the grid's faces are refused.
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>

#include "../building_mesh.h"
#include "../footprint.h"
#include "cgal_oracle.h"

namespace maquette::structures {
namespace {

// A ring of lon/lat points at (east, north) metres from (lon0, lat0), closed.
GeoPath ring(const GeographicLib::LocalCartesian& frame, std::vector<std::array<double, 2>> xy) {
  xy.push_back(xy.front());
  GeoPath out;
  for (const auto& [x, y] : xy) {
    double lat = 0, lon = 0, h = 0;
    frame.Reverse(x, y, 0, lat, lon, h);
    out.push_back({lon, lat});
  }
  return out;
}

TEST(BuildingMesh, MultiPolygonGivesOneValidShellPerPart) {
  const Grid& grid = default_grid();
  const double lon0 = 8.54, lat0 = 47.37;  // Zurich, on the north polar face
  const GeographicLib::LocalCartesian frame(lat0, lon0, 0);
  VectorFeature f;
  f.id = 3;
  f.attributes = {{"building:levels", 4}, {"roof:shape", "flat"}};
  f.geometry.type = GeometryType::MultiPolygon;
  f.geometry.polygons = {
      {{ring(frame, {{0, 0}, {40, 0}, {40, 30}, {0, 30}}),  // a courtyard block
        ring(frame, {{5, 5}, {35, 5}, {35, 25}, {5, 25}})}},
      {{ring(frame, {{10, 10}, {30, 10}, {30, 20}, {10, 20}})}},  // an island in the courtyard
      {{ring(frame, {{60, 0}, {70, 0}, {65, 12}})}}};             // a separate part
  // A DEM sloping down to the east: the lowest sample is under the separate part's east end.
  const CellId cell = grid.cell_from_point({lon0, lat0}, 14);
  Tile<float> dem(256, 1, kDemHaloPixels);
  for (int r = -kDemHaloPixels; r < 256 + kDemHaloPixels; ++r)
    for (int c = -kDemHaloPixels; c < 256 + kDemHaloPixels; ++c)
      dem.at(c, r) = float(500 - 0.25 * c);
  const LonLat centre = grid.centre(cell);
  const BuildingSite site{&grid, cell, &dem, {centre.lon, centre.lat, 0}, std::nullopt};
  const MeshObject m = building_mesh(f, {}, site);

  EXPECT_EQ(m.provenance.attributes.at("height_m"), 12);  // 4 levels of 3 m
  // The base: the lowest sample, a pixel east of the footprint's easternmost point.
  int east = -1000;
  for (const auto& polygon : f.geometry.polygons)
    for (const GeoPoint& p : polygon.rings[0]) {
      const PlanePoint q = grid.forward({p.lon, p.lat});
      const PlaneSquare sq = grid.plane_square(cell);
      east = std::max(east, int(std::floor((q.x - sq.x_min) / sq.side * 256)));
    }
  const double base = m.provenance.attributes.at("base_m").get<double>();
  EXPECT_EQ(base, 500 - 0.25 * (east + 1));
  // The area in the tangent plane at the base (~450 m up: 1.4e-4 more than at the ellipsoid),
  // by CGAL: 40 x 30 - 30 x 20 + 20 x 10 + 10 x 12 / 2 m2 there.
  const GeographicLib::LocalCartesian at_base(lat0, lon0, base);
  double area = 0;
  for (const auto& polygon : f.geometry.polygons) {
    std::vector<std::vector<std::array<double, 2>>> rings;
    for (const GeoPath& r : polygon.rings) {
      auto& xy = rings.emplace_back();
      for (const GeoPoint& p : r) {
        double x = 0, y = 0, z = 0;
        at_base.Forward(p.lat, p.lon, base, x, y, z);
        xy.push_back({x, y});
      }
    }
    area += cgal_area(rings);
  }
  EXPECT_NEAR(area, 860 * (1 + 2 * base / 6371e3), 0.01);
  EXPECT_NEAR(m.provenance.attributes.at("area_m2").get<double>(), area, 1e-9 * area);
  // float32 positions in the cell's frame: ~1e-6.
  expect_valid_solid(std::vector<double>(m.positions.begin(), m.positions.end()), m.indices,
                     area * 12, 1e-5);
}

// A 24 x 12 m gabled house (roof:height 4 m on 3 levels) and a domed one (built flat, with a
// warning): valid shells by CGAL after the move to float32, of the closed-form volume, the
// provenance naming the shape built.
TEST(BuildingMesh, PitchedRoofsAndShapesNotModelled) {
  const Grid& grid = default_grid();
  const double lon0 = 8.54, lat0 = 47.37;
  const GeographicLib::LocalCartesian frame(lat0, lon0, 0);
  const CellId cell = grid.cell_from_point({lon0, lat0}, 14);
  const Tile<float> dem(256, 1, kDemHaloPixels, 400.0f);
  const LonLat centre = grid.centre(cell);
  const BuildingSite site{&grid, cell, &dem, {centre.lon, centre.lat, 0}, std::nullopt};
  VectorFeature f;
  f.id = 5;
  f.geometry.type = GeometryType::Polygon;
  f.geometry.polygons = {{{ring(frame, {{0, 0}, {24, 0}, {24, 12}, {0, 12}})}}};
  for (const std::string shape : {"gabled", "dome"}) {
    SCOPED_TRACE(shape);
    f.attributes = {{"building:levels", 3}, {"roof:shape", shape}, {"roof:height", 4}};
    std::string warning = "stale";
    const MeshObject m = building_mesh(f, {}, site, &warning);
    const double area = m.provenance.attributes.at("area_m2").get<double>();
    const bool gabled = shape == "gabled";
    EXPECT_EQ(m.provenance.attributes.at("roof_shape"), gabled ? "gabled" : "flat");
    EXPECT_EQ(m.provenance.attributes.at("height_m"), gabled ? 13 : 9);
    EXPECT_EQ(warning, gabled ? "" : "roof:shape = \"dome\" is not modelled: built flat");
    // The tangent plane at 400 m: the area 1.3e-4 above 288 m2, the volume with it.
    const double volume = gabled ? area * 9 + area * 4 / 2 : area * 9;
    expect_valid_solid(std::vector<double>(m.positions.begin(), m.positions.end()), m.indices,
                       volume, 1e-5);
  }
}

// A 20 m square across the edge between the north polar face and an equatorial one (found by
// bisection on the latitude), and one beside it: refused, and built.
TEST(BuildingMesh, RefusesFootprintsAcrossFaceEdges) {
  const Grid& grid = default_grid();
  const double lon = 10;
  double south = 30, north = 60;
  const int polar = grid.cell_from_point({lon, north}, 0).face();
  for (int k = 0; k < 60; ++k) {
    const double mid = (south + north) / 2;
    (grid.cell_from_point({lon, mid}, 0).face() == polar ? north : south) = mid;
  }
  const double d = 1e-4;  // ~10 m of latitude
  const auto square = [&](double lat0) {
    VectorFeature f;
    f.id = 7;
    f.geometry.type = GeometryType::Polygon;
    f.geometry.polygons = {{{{{lon - d, lat0 - d},
                              {lon + d, lat0 - d},
                              {lon + d, lat0 + d},
                              {lon - d, lat0 + d},
                              {lon - d, lat0 - d}}}}};
    return f;
  };
  const Tile<float> dem(256, 1, kDemHaloPixels, 100.0f);
  for (const double lat0 : {north, north + 5 * d}) {
    const CellId cell = grid.cell_from_point({lon - d, lat0 - d}, 14);
    const LonLat centre = grid.centre(cell);
    const BuildingSite site{&grid, cell, &dem, {centre.lon, centre.lat, 0}, std::nullopt};
    if (lat0 == north) {
      try {
        building_mesh(square(lat0), {}, site);
        ADD_FAILURE() << "a footprint across a face edge was built";
      } catch (const InvalidFootprint& e) {
        EXPECT_NE(std::string(e.what()).find("edge of the grid's faces"), std::string::npos);
      }
    } else {
      const MeshObject m = building_mesh(square(lat0), {}, site);
      EXPECT_EQ(m.provenance.attributes.at("base_m"), 100);
      EXPECT_TRUE(m.uvs.empty());  // no texture window
    }
  }
}

}  // namespace
}  // namespace maquette::structures
