// Covers against brute force over every cell of a level, and against exact areas.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>

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

// Overlap and Full on every face against a brute force over every cell of the level, which uses
// only the projection (cell_from_point, inverse, boundary, vertex_neighbours) and its own
// point-in-region test, not the cover code.
//
// A cell the region's boundary passes within rho = 0.02 cell widths of (found from samples of
// the boundary every rho / 2 on the ground, measured against the boundaries of the sample's cell
// and its neighbours) is "near". A cell that is not near lies wholly inside or wholly outside
// the region: its centre decides both modes. A near cell is judged by 12 x 12 interior samples:
// one inside the region makes it Overlap, one outside makes it not Full; otherwise (the
// region's boundary skims the cell) either answer is right. The cover's own tolerance (1e-3
// cell widths) is far below both margins. Independently, lon/lat lattice points at least 0.02
// cell widths inside their cell (in face coordinates) must put that cell in Overlap when inside
// the region and keep it out of Full when outside.
struct Region {
  std::string name;
  int level;
  std::optional<Box> box;                  // cover_bbox, else cover_polygon
  std::vector<std::vector<LonLat>> rings;  // the box's rectangle, or the polygon
};

Region box_region(std::string name, int level, Box b) {
  double east = b.east;
  if (east - b.west >= 360) {
    east = b.west + 360;
  } else if (b.west > east) {
    east += 360;
  }
  return {std::move(name),
          level,
          b,
          {{{b.west, b.south}, {east, b.south}, {east, b.north}, {b.west, b.north}}}};
}

bool in_region(const Region& r, LonLat p) {
  if (r.box) return r.box->contains(p);
  for (const double shift : {-360.0, 0.0, 360.0}) {
    const double lon = p.lon + shift;
    bool inside = false;
    for (const auto& ring : r.rings) {
      for (size_t i = 0; i < ring.size(); ++i) {
        const LonLat a = ring[i], b = ring[(i + 1) % ring.size()];
        if ((a.lat > p.lat) != (b.lat > p.lat) &&
            lon < a.lon + (p.lat - a.lat) / (b.lat - a.lat) * (b.lon - a.lon)) {
          inside = !inside;
        }
      }
    }
    if (inside) return true;
  }
  return false;
}

using Vec3 = std::array<double, 3>;

Vec3 unit_vector(LonLat p) {
  const double lon = p.lon * M_PI / 180, lat = p.lat * M_PI / 180;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// Euclidean distance from p to the segment a b.
double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  Vec3 d, e;
  double dd = 0, de = 0;
  for (size_t i = 0; i < 3; ++i) {
    d[i] = b[i] - a[i];
    e[i] = p[i] - a[i];
    dd += d[i] * d[i];
    de += d[i] * e[i];
  }
  const double t = dd > 0 ? std::clamp(de / dd, 0.0, 1.0) : 0;
  double sum = 0;
  for (size_t i = 0; i < 3; ++i) sum += (e[i] - t * d[i]) * (e[i] - t * d[i]);
  return std::sqrt(sum);
}

void check_against_brute_force(const Region& region) {
  SCOPED_TRACE(region.name);
  const auto& grid = static_cast<const RHealpixGrid&>(default_grid());
  const int level = region.level;
  const auto cover = [&](Containment mode) {
    const auto& b = region.box;
    return b ? grid.cover_bbox(b->west, b->south, b->east, b->north, level, mode)
             : grid.cover_polygon(region.rings, level, mode);
  };
  const auto overlap = cover(Containment::Overlap), full = cover(Containment::Full),
             centre = cover(Containment::Centre);
  EXPECT_TRUE(std::includes(centre.begin(), centre.end(), full.begin(), full.end()));
  EXPECT_TRUE(std::includes(overlap.begin(), overlap.end(), centre.begin(), centre.end()));
  const auto has = [](const std::vector<CellId>& v, CellId c) {
    return std::binary_search(v.begin(), v.end(), c);
  };

  // Near cells, from samples of the region's boundary.
  const double rho = 0.02 * std::sqrt(grid.area(level)) / grid.projection().radius();
  std::set<CellId> near;
  struct Outline {
    Vec3 centre;
    double radius = 0;  // of the ball around the centre holding the boundary
    std::vector<Vec3> boundary;
  };
  std::map<CellId, Outline> outlines;
  const auto distance = [](const Vec3& a, const Vec3& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  };
  for (const auto& ring : region.rings) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const LonLat a = ring[i], b = ring[(i + 1) % ring.size()];
      // The ground length is at most that of the segment with the widest parallel spacing.
      const double widest = a.lat * b.lat <= 0
                                ? 1
                                : std::cos(std::min(std::abs(a.lat), std::abs(b.lat)) * M_PI / 180);
      const double length = std::hypot(b.lat - a.lat, widest * (b.lon - a.lon)) * M_PI / 180;
      const int n = std::max(1, int(std::ceil(length / (rho / 2))));
      for (int j = 0; j < n; ++j) {
        const double t = double(j) / n;
        const LonLat q{a.lon + t * (b.lon - a.lon), a.lat + t * (b.lat - a.lat)};
        const CellId cell = grid.cell_from_point(q, level);
        near.insert(cell);
        const Vec3 v = unit_vector(q);
        for (const CellId other : grid.vertex_neighbours(cell)) {
          auto [it, added] = outlines.try_emplace(other);
          Outline& o = it->second;
          if (added) {
            o.centre = unit_vector(grid.centre(other));
            for (const LonLat& p : grid.boundary(other, 16)) {
              o.boundary.push_back(unit_vector(p));
              o.radius = std::max(o.radius, distance(o.centre, o.boundary.back()));
            }
          }
          if (near.count(other) || distance(v, o.centre) > o.radius + rho) continue;
          for (size_t k = 0; k + 1 < o.boundary.size(); ++k) {
            if (segment_distance(v, o.boundary[k], o.boundary[k + 1]) < rho) {
              near.insert(other);
              break;
            }
          }
        }
      }
    }
  }

  std::vector<std::string> errors;
  const auto expect = [&errors](bool ok, const std::string& what, CellId cell) {
    if (!ok) errors.push_back(what + " " + cell.ToText());
  };
  int near_checked = 0, near_open = 0;
  constexpr int kSamples = 12;
  for (const CellId cell : test::all_cells(level)) {
    const PlaneSquare sq = grid.plane_square(cell);
    const auto sample = [&](double fu, double fv) {
      return in_region(region, grid.inverse({sq.x_min + fu * sq.side, sq.y_max - fv * sq.side}));
    };
    if (!near.count(cell)) {
      const bool in = sample(0.5, 0.5);
      expect(has(overlap, cell) == in, in ? "Overlap misses" : "Overlap has", cell);
      expect(has(full, cell) == in, in ? "Full misses" : "Full has", cell);
      continue;
    }
    bool any_in = false, all_in = true;
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        const bool in = sample((i + 0.5) / kSamples, (j + 0.5) / kSamples);
        any_in = any_in || in;
        all_in = all_in && in;
      }
    }
    if (any_in) expect(has(overlap, cell), "Overlap misses near", cell);
    if (!all_in) expect(!has(full, cell), "Full has near", cell);
    ++(any_in && !all_in ? near_checked : near_open);
  }
  // Most near cells are crossed by the boundary, so that both modes are checked.
  EXPECT_GT(near_checked, near_open);

  // Lattice points well inside their cell.
  double west = 1e300, east = -1e300, south = 90, north = -90;
  for (const auto& ring : region.rings) {
    for (const LonLat& p : ring) {
      west = std::min(west, p.lon);
      east = std::max(east, p.lon);
      south = std::min(south, p.lat);
      north = std::max(north, p.lat);
    }
  }
  west -= 5;
  east += 5;
  south = std::max(-90.0, south - 3);
  north = std::min(90.0, north + 3);
  const double n = double(int64_t(1) << level);
  const auto depth = [n](double x) {
    const double i = std::min(std::floor(x * n), n - 1);
    return std::min(x * n - i, i + 1 - x * n);
  };
  constexpr int kLattice = 250;
  for (int i = 0; i <= kLattice; ++i) {
    for (int j = 0; j <= kLattice; ++j) {
      const LonLat p{west + (east - west) * (i + 0.37) / kLattice,
                     south + (north - south) * j / kLattice};
      const FacePoint f = grid.projection().to_face(p);
      if (std::min(depth(f.u), depth(f.v)) < 0.02) continue;
      const CellId cell = grid.cell_from_point(p, level);
      if (in_region(region, p)) {
        expect(has(overlap, cell), "Overlap misses lattice", cell);
      } else {
        expect(!has(full, cell), "Full has lattice", cell);
      }
    }
  }
  std::sort(errors.begin(), errors.end());
  errors.erase(std::unique(errors.begin(), errors.end()), errors.end());
  std::string first;
  for (size_t i = 0; i < std::min<size_t>(errors.size(), 10); ++i) first += "\n  " + errors[i];
  EXPECT_TRUE(errors.empty()) << errors.size() << " wrong cells:" << first;
}

TEST(Cover, OverlapAndFullMatchBruteForceOnPolarFaces) {
  const std::vector<Region> regions = {
      {"around the north pole",
       5,
       std::nullopt,
       {{{-170, 70.3},
         {-100, 76.1},
         {-20, 71.7},
         {60, 78.2},
         {130, 73.9},
         {190, 70.3},
         {190, 90},
         {-170, 90}}}},
      box_region("polar cap", 4, {-180, 75.1, 180, 90}),
      box_region("touching the pole", 6, {10.3, 73.3, 100.7, 90}),
      box_region("across the antimeridian", 5, {150.3, 60.2, -160.6, 79.7}),
      {"south face, concave with a hole",
       6,
       std::nullopt,
       {{{-60.3, -50.1}, {30.7, -47.9}, {20.2, -80.3}, {-10.1, -62.2}, {-70.6, -75.4}},
        {{-40.2, -60.1}, {-30.3, -58.7}, {-35.1, -66.6}}}},
      box_region("north face and an equatorial face", 5, {-30.1, 30.3, 60.1, 55.2}),
      box_region("south pole, across the antimeridian", 5, {120.4, -90, -110.2, -66.3}),
  };
  for (const Region& region : regions) check_against_brute_force(region);
}

// A box whose edges run along cell edges (the meridians 45 and 135 are axes of the north face,
// the parallel is a ring of Chebyshev distance 1/4 around the pole): exactly the 16 cells of a
// quadrant at level 4, in every mode, though 12 of them touch the box's boundary.
TEST(Cover, BoxAlongPolarCellEdges) {
  const auto& grid = static_cast<const RHealpixGrid&>(default_grid());
  const double lat = grid.projection().polar_latitude(kFaceN, 0.25);
  for (const auto mode : {Containment::Centre, Containment::Overlap, Containment::Full}) {
    const auto cells = grid.cover_bbox(45, lat, 135, 90, 4, mode);
    ASSERT_EQ(cells.size(), 16U);
    for (const CellId cell : cells) {
      const LonLat c = grid.centre(cell);
      EXPECT_TRUE(c.lon > 45 && c.lon < 135 && c.lat > lat) << cell.ToText();
    }
  }
}

}  // namespace
}  // namespace maquette
