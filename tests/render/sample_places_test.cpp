// SamplePlaces (formats/render/sample_places.h) against the exact places: each sample's lon/lat
// against the grid's own pixel centre (core/halo.h pixel_source + pixel_centre), and its ENU
// position at several heights against PROJ's east-north-up frame at the eye (tests/support
// proj_enu.h), on heights above the ellipsoid; for a cell in mid-latitudes, one on a face's edge
// (its halo ring on the neighbouring face, turned) and one next to a pole; and each sample's point
// of the grid's plane against Grid::forward; and SamplePlaces::ground against `at`, bit for bit.
#include "render/sample_places.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "core/halo.h"
#include "core/tile.h"
#include "proj_enu.h"

namespace maquette {
namespace {

struct Worst {
  double degrees = 0, metres = 0;
  int samples = 0;
  double plane = 0;   // metres of the grid's plane from Grid::forward of the exact centre
  int off_face = 0;   // samples read from another face (no plane point)
  int misplaced = 0;  // samples with a plane point off their face, or none on it
  int ground = 0;     // samples whose ground() base or up differ from at()'s in a bit
};

constexpr int kHalo = 2;  // the terrain's two rings: the drawn one and the normals' (terrain_scene)

Worst worst_error(CellId cell, int size, GeodeticPoint eye) {
  const Grid& grid = default_grid();
  const EnuFrame frame(eye);
  const EllipsoidalHeights on_ellipsoid;
  const SamplePlaces places(grid, cell, size, kHalo, frame, on_ellipsoid);
  const test::ProjEnu enu(eye.lon, eye.lat, eye.height);
  const int level = cell.level() + log2_tile_size(size);
  Worst w;
  for (int row = -kHalo; row < size + kHalo; ++row)
    for (int col = -kHalo; col < size + kHalo; ++col) {
      const auto source = pixel_source(grid, cell, size, col, row);
      const SamplePlace& place = places.at(col, row);
      const SamplePlace ground = places.ground(col, row);
      w.ground += std::memcmp(ground.base.data(), place.base.data(), sizeof place.base) != 0 ||
                  std::memcmp(ground.up.data(), place.up.data(), sizeof place.up) != 0;
      EXPECT_EQ(place.known, source.has_value()) << col << " " << row;
      if (!source) continue;
      const LonLat exact = pixel_centre(grid, *source, level);
      if (source->face == cell.face()) {
        const PlanePoint q = grid.forward(exact);
        w.plane = std::max({w.plane, std::abs(place.plane.x - q.x), std::abs(place.plane.y - q.y)});
        w.misplaced += std::isnan(place.plane.x);
      } else {
        ++w.off_face;
        w.misplaced += !std::isnan(place.plane.x);
      }
      w.degrees = std::max({w.degrees, std::abs(place.position.lon - exact.lon),
                            std::abs(place.position.lat - exact.lat)});
      for (const double h : {-400.0, 0.0, 2500.0, 8800.0}) {
        const auto oracle = enu(exact, h);
        double d2 = 0;
        for (size_t k = 0; k < 3; ++k) {
          const double d = place.base[k] + h * place.up[k] - oracle[k];
          d2 += d * d;
        }
        w.metres = std::max(w.metres, std::sqrt(d2));
      }
      ++w.samples;
    }
  return w;
}

// Within a thousandth of a sample of PROJ (the lattice's interpolation error grows as its
// interval squared over the earth's radius: a few millimetres for 35 m samples).
TEST(SamplePlaces, WithinAThousandthOfASampleOfProj) {
  const Grid& grid = default_grid();
  struct Case {
    const char* name;
    CellId cell;
    int size;
  };
  const CellId zion = grid.cell_from_point({-113.0, 37.3}, 10);
  // A level-8 cell on a face's edge (column 0 of its face), and one holding a pole's neighbourhood.
  const CellId edge = CellId::FromFaceColRow(zion.face(), 8, 0, 77);
  const CellId polar = grid.cell_from_point({30.0, 89.5}, 7);
  // Cells on face N that its diagonals cross (the meridians 0 and 90 E), where rows of samples
  // bend by about 50 degrees on the ground (a lattice there was off by 2.4 samples).
  const CellId diagonal0 = grid.cell_from_point({0.0005, 50.0}, 10),
               diagonal90 = grid.cell_from_point({90.0005, 65.0}, 9);
  for (const Case& c : {Case{"zion 256", zion, 256}, Case{"zion 64", zion, 64},
                        Case{"face edge", edge, 256}, Case{"polar", polar, 256},
                        Case{"diagonal 0", diagonal0, 256}, Case{"diagonal 90", diagonal90, 64}}) {
    const LonLat centre = grid.centre(c.cell);
    // The eye 20 km from the cell's centre, 3 km up: ENU coordinates of tens of kilometres.
    const Worst w = worst_error(c.cell, c.size, {centre.lon, centre.lat - 0.18, 3000});
    EXPECT_EQ(w.samples, (c.size + 2 * kHalo) * (c.size + 2 * kHalo)) << c.name;
    // Measured: 4 mm and 1.4e-8 degrees at Zion (35 m and 140 m samples), 5 cm and 5.5e-8
    // degrees on the face edge (140 m samples), 0 at the pole and on the diagonals (placed
    // exactly).
    const double sample = grid.level_info(c.cell.level(), c.size).pixel_m;
    EXPECT_LE(w.metres, 1e-3 * sample) << c.name;
    EXPECT_LE(w.degrees * 111e3, 1e-3 * sample) << c.name;
    // The plane points: the grid's forward projection of the centres on the cell's face (1e-6 of
    // a sample: the same point), none for those read from another face.
    EXPECT_LE(w.plane, 1e-6 * sample) << c.name;
    EXPECT_EQ(w.misplaced, 0) << c.name;
    EXPECT_EQ(w.ground, 0) << c.name;
    EXPECT_EQ(w.off_face > 0, std::string(c.name) == "face edge") << c.name;
  }
}

}  // namespace
}  // namespace maquette
