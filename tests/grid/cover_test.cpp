// Covers against brute force over every cell of a level, and against exact areas.
#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "core/region.h"
#include "rhealpix/rhealpix_grid.h"
#include "test_util.h"

namespace maquette {
namespace {

struct Box {
  double west, south, east, north;
  // With a margin (degrees) inside the box, or outside it when negative.
  bool contains(LonLat p, double margin = 0) const {
    const double lon = west + std::remainder(p.lon - west - 180, 360) + 180;  // in [west, west+360)
    const double width = west <= east ? east - west : east - west + 360;
    return lon >= west + margin && lon <= west + width - margin && p.lat >= south + margin &&
           p.lat <= north - margin;
  }
  // Exact area on the ellipsoid from the authalic latitudes (well inside one face width).
  double area() const {
    const auto& a = static_cast<const RHealpixGrid&>(default_grid()).projection().authalic();
    const double width = (west <= east ? east - west : east - west + 360) * M_PI / 180;
    const double r = a.radius();
    return r * r * width *
           (std::sin(a.authalic(north * M_PI / 180)) - std::sin(a.authalic(south * M_PI / 180)));
  }
};

// Edges avoid cell centres: a centre exactly on the boundary follows the crossing-number rule.
const Box kBoxes[] = {
    {170, -10, -170, 10},      // across the antimeridian
    {-180, 75, 180, 90},       // polar cap
    {100.1, -90, 160.1, -70},  // reaching the south pole
    {-30.1, 30, 60.1, 50},     // across the north face's edge
    {-5.5, 40.2, 12.3, 47.9},
};

TEST(Cover, CentreModeMatchesBruteForce) {
  const Grid& grid = default_grid();
  const int level = 5;
  for (const Box& box : kBoxes) {
    std::vector<CellId> expected;
    for (const CellId cell : test::all_cells(level)) {
      if (box.contains(grid.centre(cell))) expected.push_back(cell);
    }
    EXPECT_EQ(grid.cover_bbox(box.west, box.south, box.east, box.north, level, Containment::Centre),
              expected)
        << box.west << " " << box.south;
  }
}

TEST(Cover, ModesAreNestedAndSound) {
  const Grid& grid = default_grid();
  const int level = 5;
  for (const Box& box : kBoxes) {
    const auto cover = [&](Containment m) {
      return grid.cover_bbox(box.west, box.south, box.east, box.north, level, m);
    };
    const auto full = cover(Containment::Full), centre = cover(Containment::Centre),
               overlap = cover(Containment::Overlap);
    EXPECT_TRUE(std::includes(centre.begin(), centre.end(), full.begin(), full.end()));
    EXPECT_TRUE(std::includes(overlap.begin(), overlap.end(), centre.begin(), centre.end()));
    for (const CellId cell : test::all_cells(level)) {
      const auto ring = grid.boundary(cell, 8);
      const auto in = [&](double margin) {
        return [&box, margin](LonLat p) { return box.contains(p, margin); };
      };
      const bool all_in = std::all_of(ring.begin(), ring.end(), in(-1e-9));
      const bool some_strictly_in = std::any_of(ring.begin(), ring.end(), in(1e-9));
      if (std::binary_search(full.begin(), full.end(), cell)) {
        EXPECT_TRUE(all_in) << cell.ToText();
      }
      if (some_strictly_in) {
        EXPECT_TRUE(std::binary_search(overlap.begin(), overlap.end(), cell)) << cell.ToText();
      }
      // On equatorial faces cells are lon/lat rectangles and Full is exact.
      if (all_in && cell.face() != kFaceN && cell.face() != kFaceS) {
        EXPECT_TRUE(std::binary_search(full.begin(), full.end(), cell)) << cell.ToText();
      }
    }
  }
}

TEST(Cover, AreaMatchesTheBox) {
  const Grid& grid = default_grid();
  for (const Box& box : kBoxes) {
    const int level = 10;  // cells of ~9 km: the box edges cut ~1% of the area
    const auto cells =
        grid.cover_bbox(box.west, box.south, box.east, box.north, level, Containment::Centre);
    const double area = double(cells.size()) * grid.area(level);
    EXPECT_NEAR(area, box.area(), 0.01 * box.area()) << box.west << " " << box.south;
  }
}

TEST(Cover, CompactRoundTrip) {
  const Grid& grid = default_grid();
  const auto cells = grid.cover_bbox(-20, -80, 60, 10, 6, Containment::Overlap);
  const auto compacted = compact(cells);
  EXPECT_LT(compacted.size(), cells.size() / 4);
  EXPECT_EQ(uncompact(compacted, 6), cells);
}

TEST(Cover, WholeWorldAndPolygonWithHole) {
  const Grid& grid = default_grid();
  EXPECT_EQ(grid.cover_bbox(-180, -90, 180, 90, 3, Containment::Full), test::all_cells(3));
  const std::vector<std::vector<LonLat>> rings = {
      {{0, 0}, {40, 0}, {40, 40}, {0, 40}, {0, 0}},
      {{10, 10}, {10, 30}, {30, 30}, {30, 10}},
  };
  const auto cells = grid.cover_polygon(rings, 6, Containment::Centre);
  ASSERT_FALSE(cells.empty());
  for (const CellId cell : cells) {
    const LonLat c = grid.centre(cell);
    EXPECT_FALSE(c.lon > 10 && c.lon < 30 && c.lat > 10 && c.lat < 30) << cell.ToText();
  }
  EXPECT_TRUE(std::binary_search(cells.begin(), cells.end(), grid.cell_from_point({5, 5}, 6)));
  EXPECT_THROW(grid.cover_polygon({{{0, 0}, {1, 1}}}, 3, Containment::Full), Error);
  EXPECT_THROW(grid.cover_bbox(0, 10, 5, 5, 3, Containment::Full), Error);
}

}  // namespace
}  // namespace maquette
