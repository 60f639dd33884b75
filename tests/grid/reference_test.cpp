// The reference points of DESIGN.md ("The grid") and input validation.
#include <gtest/gtest.h>

#include "core/error.h"
#include "rhealpix/rhealpix_grid.h"

namespace maquette {
namespace {

struct Reference {
  LonLat p;
  double x, y;
  const char* level1;
  const char* level3;
  const char* level8;
};

constexpr Reference kReferences[] = {
    {{10, 45}, -11353356.295994, 14710666.318621, "N1", "N110", "N11011323"},
    {{0, 0}, 0, 0, "Q2", "Q200", "Q20000000"},
    {{174.77, -36.85}, 19433559.233711, -4488402.278058, "R3", "R333", "R33330021"},
    {{-43.2, -22.9}, -4803626.245330, -2909546.059693, "P3", "P320", "P32002121"},
};

TEST(Reference, Points) {
  const Grid& grid = default_grid();
  for (const Reference& r : kReferences) {
    const PlanePoint xy = grid.forward(r.p);
    EXPECT_NEAR(xy.x, r.x, 1e-6) << r.level8;
    EXPECT_NEAR(xy.y, r.y, 1e-6) << r.level8;
    EXPECT_EQ(grid.cell_from_point(r.p, 1).ToText(), r.level1);
    EXPECT_EQ(grid.cell_from_point(r.p, 3).ToText(), r.level3);
    EXPECT_EQ(grid.cell_from_point(r.p, 8).ToText(), r.level8);
    const LonLat back = grid.inverse(xy);
    EXPECT_NEAR(back.lon, r.p.lon, 1e-12);
    EXPECT_NEAR(back.lat, r.p.lat, 1e-12);
  }
}

TEST(Reference, Areas) {
  const Grid& grid = default_grid();
  EXPECT_NEAR(grid.area(0), 8.501093695401478e13, 1e-15 * 8.5e13);
  EXPECT_NEAR(grid.area(12), 5.067046699e6, 1e-3);
  const LevelInfo info = grid.level_info(12, 256);
  EXPECT_DOUBLE_EQ(info.area_m2, grid.area(12));
  EXPECT_DOUBLE_EQ(info.cell_side_m, std::sqrt(grid.area(12)));
  EXPECT_DOUBLE_EQ(info.pixel_m, info.cell_side_m / 256);
  EXPECT_NEAR(info.plane_side_m, 6371007.180918 * M_PI / 2 / 4096, 1e-6);
}

TEST(Reference, TieRules) {
  const Grid& grid = default_grid();
  // Longitude 180 is -180 (face O); face edges go to the right face; the equator (an inner
  // edge at level 1) to the lower row.
  EXPECT_EQ(grid.cell_from_point({180, 0}, 0).ToText(), "O");
  EXPECT_EQ(grid.cell_from_point({-180, 0}, 0).ToText(), "O");
  EXPECT_EQ(grid.cell_from_point({-90, 10}, 0).ToText(), "P");
  EXPECT_EQ(grid.cell_from_point({0, 10}, 0).ToText(), "Q");
  EXPECT_EQ(grid.cell_from_point({90, 10}, 0).ToText(), "R");
  EXPECT_EQ(grid.cell_from_point({45, 0}, 1).ToText(), "Q3");
  EXPECT_EQ(grid.cell_from_point({540, 0}, 0).ToText(), "O");
  EXPECT_EQ(grid.cell_from_point({-450, 0}, 0).ToText(), "P");
  // The poles: the centre of a polar face, so the cell right of and below it, whatever the
  // longitude.
  for (const double lon : {-180.0, -100.0, 0.0, 45.0, 123.0}) {
    EXPECT_EQ(grid.cell_from_point({lon, 90}, 3).ToText(), "N300");
    EXPECT_EQ(grid.cell_from_point({lon, -90}, 3).ToText(), "S300");
  }
}

TEST(Reference, RejectsBadInput) {
  const Grid& grid = default_grid();
  EXPECT_THROW(grid.cell_from_point({0, 90.0000001}, 3), Error);
  EXPECT_THROW(grid.cell_from_point({0, -91}, 3), Error);
  EXPECT_THROW(grid.cell_from_point({0, NAN}, 3), Error);
  EXPECT_THROW(grid.cell_from_point({INFINITY, 0}, 3), Error);
  EXPECT_THROW(grid.forward({0, 100}), Error);
  EXPECT_THROW(grid.cell_from_point({0, 0}, 30), Error);
  EXPECT_THROW(grid.cell_from_point({0, 0}, -1), Error);
  EXPECT_THROW(grid.inverse({1e7, 1.2e7}), Error);  // the empty square right of N
  try {
    grid.cell_from_point({0, 95}, 3);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("95"), std::string::npos) << e.what();
  }
}

TEST(Reference, BatchedMatchesSingle) {
  const Grid& grid = default_grid();
  std::vector<LonLat> points;
  for (const Reference& r : kReferences) points.push_back(r.p);
  std::vector<CellId> cells(points.size());
  grid.cells_from_points(points, 8, cells);
  for (size_t i = 0; i < points.size(); ++i) EXPECT_EQ(cells[i].ToText(), kReferences[i].level8);
  std::vector<CellId> too_few(1);
  EXPECT_THROW(grid.cells_from_points(points, 8, too_few), Error);
}

}  // namespace
}  // namespace maquette
