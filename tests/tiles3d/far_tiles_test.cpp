// Fine tiles far from the export's frame origin keep centimetre positions: two level-12 cells
// ~4,900 km apart (lon 1 and 89 on the equator, the frame between them) of a flat DEM 1000 m above
// the ellipsoid, exported as 3D Tiles and as one GLB with 20-bit positions. Every decoded vertex
// (Draco, plus its node's translation) is compared with its true position: the rHEALPix pixel
// corner nearest to it (PROJ) at 1000 m (or the skirt's depth), in ECEF by GeographicLib. Float
// positions in the one export frame were off by up to ~0.25 m there (floats keep 0.5 m at 5,000
// km).
#include <gtest/gtest.h>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <iostream>
#include <numbers>

#include "run_cli.h"
#include "synthetic_raster.h"
#include "test_tiles.h"
#include "tileset_reader.h"

namespace maquette::test {
namespace {

constexpr int kTile = 16, kFineLevel = 12;
constexpr double kHeight = 1000;
constexpr const char* kRhealpix = "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0";

struct FarCells {
  std::string store;
  std::vector<CellId> cells;
};

const FarCells& far_cells() {
  static const FarCells f = [] {
    const Grid& grid = default_grid();
    FarCells out{
        temp_dir() + "/far.mqt",
        {grid.cell_from_point({1, 1}, kFineLevel), grid.cell_from_point({89, 1}, kFineLevel)}};
    auto store = Store::open(out.store, Store::Mode::Create);
    store->create_layer(layer_info("dem", DType::F32, 1, kTile, kFineLevel));
    Store::Batch batch(*store);
    for (CellId c : out.cells)
      batch.put_tile("dem", c, make_tile<float>(grid, c, kTile, 1, [](const TileSample&, int) {
                       return kHeight;
                     }));
    batch.commit();
    return out;
  }();
  return f;
}

// The largest distance (m) between decoded vertices, given as geodetic lon, lat, height, and
// their true positions: on the pixel corners of the plane at 1000 m, or the skirt's depth below.
class VertexErrors {
 public:
  void add(double lon, double lat, double h) {
    const double pixel = std::ldexp(std::numbers::pi / 2 * kAuthalicRadius, -(kFineLevel + 4));
    auto [x, y] = to_plane_(lon, lat);
    // Face Q's top-left corner is (0, pi/4 R) in the plane; corners are whole pixels from it.
    const double y0 = std::numbers::pi / 4 * kAuthalicRadius;
    x = std::round(x / pixel) * pixel;
    y = y0 - std::round((y0 - y) / pixel) * pixel;
    const auto [clon, clat] = to_lonlat_(x, y);
    const double skirt = 2 * default_grid().level_info(kFineLevel, kTile).pixel_m;
    const double want_h = std::abs(h - kHeight) < skirt / 2 ? kHeight : kHeight - skirt;
    double a[3], b[3];
    const auto& wgs84 = GeographicLib::Geocentric::WGS84();
    wgs84.Forward(lat, lon, h, a[0], a[1], a[2]);
    wgs84.Forward(clat, clon, want_h, b[0], b[1], b[2]);
    worst = std::max(worst, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    ++count;
  }
  double worst = 0;
  size_t count = 0;

 private:
  static constexpr double kAuthalicRadius = 6371007.180918;
  Projector to_plane_{"EPSG:4326", kRhealpix}, to_lonlat_{kRhealpix, "EPSG:4326"};
};

std::string cell_list() {
  std::string s;
  for (CellId c : far_cells().cells) s += " " + c.ToText();
  return s;
}

TEST(FarTiles, Tiles3dVerticesWithinOneCentimetre) {
  const std::string dir = temp_dir() + "/tiles";
  const auto r = run_maquette("export tiles3d " + far_cells().store + " " + dir +
                              " --dem dem --levels 12..12 --position-bits 20");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Export e = read_export(dir);
  const auto m = e.tileset["root"]["transform"].get<std::vector<double>>();
  VertexErrors errors;
  for (CellId c : far_cells().cells) {
    const auto it = e.glbs.find("tiles/12/" + c.ToText() + ".glb");
    ASSERT_NE(it, e.glbs.end()) << c.ToText();
    for (const Pos& p : it->second.primitives.at(0).positions) {
      const auto g = geodetic(m, p);
      errors.add(g[0], g[1], g[2]);
    }
  }
  std::cout << "3D Tiles: " << errors.count << " vertices, worst " << errors.worst * 1000
            << " mm from the truth\n";
  EXPECT_EQ(errors.count, 2u * ((kTile + 1) * (kTile + 1) + 4 * kTile));
  EXPECT_LT(errors.worst, 0.01);
  EXPECT_NE(gltf_validator_passes(dir), false);
}

TEST(FarTiles, GlbVerticesWithinOneCentimetre) {
  const std::string out = temp_dir() + "/far.glb";
  const auto r = run_maquette("export glb " + far_cells().store + " " + out +
                              " --dem dem --position-bits 20 --cells" + cell_list());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Glb glb = read_glb(out);
  const auto& origin = glb.json["asset"]["extras"]["maquette_frame"]["origin"];
  const GeographicLib::LocalCartesian enu(origin["lat"].get<double>(), origin["lon"].get<double>(),
                                          0);
  VertexErrors errors;
  ASSERT_EQ(glb.primitives.size(), 2u);
  for (const DecodedPrimitive& prim : glb.primitives)
    for (const Pos& p : prim.positions) {
      double lat, lon, h;
      enu.Reverse(p[0], -p[2], p[1], lat, lon, h);  // x east, y up, z south
      errors.add(lon, lat, h);
    }
  std::cout << "GLB: " << errors.count << " vertices, worst " << errors.worst * 1000
            << " mm from the truth\n";
  EXPECT_LT(errors.worst, 0.01);
}

}  // namespace
}  // namespace maquette::test
