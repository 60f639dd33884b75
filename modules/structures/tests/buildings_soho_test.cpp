// The 158 OSM footprints of London Soho (read with GDAL) on a synthetic DEM: every one gives a
// solid CGAL finds closed, outward and free of self-intersection, of volume area x height (the
// area by CGAL's Polygon_2), and a mesh standing on the terrain (nothing floats).
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <filesystem>

#include "../building_mesh.h"
#include "../building_solid.h"
#include "../footprint.h"
#include "cgal_oracle.h"
#include "soho_scene.h"

namespace maquette::structures {
namespace {

const std::string kSoho =
    std::string(MAQUETTE_SHARED_DIR) + "/data/buildings/london_soho_buildings_wgs84.geojson";

std::vector<std::vector<std::array<double, 2>>> plane_rings(
    const GeoPolygon& polygon, const GeographicLib::LocalCartesian& f) {
  // At the frame's own height: the tangent plane there.
  std::vector<std::vector<std::array<double, 2>>> rings;
  for (const GeoPath& ring : polygon.rings) {
    auto& r = rings.emplace_back();
    for (const GeoPoint& p : ring) {
      double x = 0, y = 0, z = 0;
      f.Forward(p.lat, p.lon, f.HeightOrigin(), x, y, z);
      r.push_back({x, y});
    }
  }
  return rings;
}

// Every test reads the Soho footprints of ../shared/data: skipped without them.
class BuildingsSoho : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kSoho)) GTEST_SKIP() << kSoho << " is absent (../shared/data)";
  }
};

TEST_F(BuildingsSoho, EverySolidIsValidByCgal) {
  const SohoScene scene(kSoho);
  ASSERT_EQ(scene.footprints.size(), 158u);
  for (const VectorFeature& f : scene.footprints) {
    const GeoPoint& first = f.geometry.polygons[0].rings[0][0];
    const GeographicLib::LocalCartesian frame(first.lat, first.lon, 0);
    const auto rings = plane_rings(f.geometry.polygons[0], frame);
    const Footprint fp = make_footprint(rings);
    const double height = 4 + double(f.id % 9) * 3.5;
    const Solid s = extrude(fp, height);
    const double area = cgal_area(rings);
    SCOPED_TRACE("feature " + std::to_string(f.id));
    expect_valid_solid(s.positions, s.indices, area * height);
    EXPECT_EQ(solid_problem(s, area * height), "") << "feature " << f.id;
  }
}

TEST_F(BuildingsSoho, MeshesStandOnTheTerrainInTheirCell) {
  const SohoScene scene(kSoho);
  ASSERT_EQ(scene.footprints.size(), 158u);
  const Grid& grid = default_grid();
  double lowest_gap = INFINITY;
  for (const VectorFeature& f : scene.footprints) {
    const GeoPoint& first = f.geometry.polygons[0].rings[0][0];
    const BuildingSite site = scene.site(f);
    const CellId cell = site.cell;
    const LonLat centre = grid.centre(cell);
    const MeshObject m = building_mesh(f, {}, site);

    const double height = m.provenance.attributes.at("height_m").get<double>();
    const double base = m.provenance.attributes.at("base_m").get<double>();
    const double area = m.provenance.attributes.at("area_m2").get<double>();
    EXPECT_EQ(height, 10);  // no tags: the default
    SCOPED_TRACE("feature " + std::to_string(f.id));
    // float32 positions in the cell's frame, hundreds of metres from its origin: ~1e-5 m.
    expect_valid_solid(std::vector<double>(m.positions.begin(), m.positions.end()), m.indices,
                       area * height, 1e-5);
    EXPECT_NEAR(area, cgal_area(plane_rings(f.geometry.polygons[0], {first.lat, first.lon, base})),
                1e-9 * area);

    // The anchor: the first vertex is the footprint's first point at the base height.
    const GeographicLib::LocalCartesian frame(centre.lat, centre.lon, 0);
    double lat = 0, lon = 0, h = 0;
    frame.Reverse(m.positions[0], m.positions[1], m.positions[2], lat, lon, h);
    EXPECT_NEAR(lon, first.lon, 1e-8);
    EXPECT_NEAR(lat, first.lat, 1e-8);
    EXPECT_NEAR(h, base, 1e-3);
    EXPECT_EQ(grid.cell_from_point({lon, lat}, kSohoLevel), cell);

    // Nothing floats: the terrain at every point of a 0.5 m lattice inside the footprint is at
    // or above the base (within 1 cm: the smooth terrain dips by millimetres between the pixel
    // centres the DEM samples); and the base is no lower than the terrain within 10 m of the
    // footprint (the pixels touched and their neighbours: 2.5 pixels of ~2.2 m, sheared by the
    // polar face up to ~1.5x; within 10 cm, the lattice's step on these slopes).
    const GeographicLib::LocalCartesian local(first.lat, first.lon, 0);
    const auto rings = plane_rings(f.geometry.polygons[0], local);
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const auto& p : rings[0]) {
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
    double under = INFINITY, around = INFINITY;
    for (double y = y0 - 10; y <= y1 + 10; y += 0.5)
      for (double x = x0 - 10; x <= x1 + 10; x += 0.5) {
        double plat = 0, plon = 0, ph = 0;
        local.Reverse(x, y, 0, plat, plon, ph);
        const double z = soho_terrain(grid.forward({plon, plat}));
        around = std::min(around, z);
        bool in = false;
        for (const auto& ring : rings)
          for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
            if ((ring[i][1] > y) != (ring[j][1] > y) &&
                x < ring[j][0] +
                        (y - ring[j][1]) / (ring[i][1] - ring[j][1]) * (ring[i][0] - ring[j][0]))
              in = !in;
        if (in) under = std::min(under, z);
      }
    EXPECT_LE(base, under + 0.01) << "feature " << f.id << " floats";
    EXPECT_GE(base, around - 0.1) << "feature " << f.id << " sinks deeper than its surroundings";
    lowest_gap = std::min(lowest_gap, under - base);
  }
  EXPECT_LT(lowest_gap, 0.5);  // some building stands within 0.5 m of its lowest ground point
}

}  // namespace
}  // namespace maquette::structures
