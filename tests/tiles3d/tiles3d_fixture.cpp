#include "tiles3d_fixture.h"

#include <cmath>

#include "run_cli.h"
#include "store/store.h"
#include "test_tiles.h"

namespace maquette::test {
namespace {

RawTile dem_tile(const Grid& grid, CellId cell) {
  return make_tile<float>(grid, cell, kTileSize, 1,
                          [](const TileSample& s, int) { return dem_field(s.lonlat); });
}

Tiles3dFixture build() {
  const Grid& grid = default_grid();
  Tiles3dFixture f;
  f.store_path = temp_dir() + "/tiles3d.maquette";
  f.block = block_of_four(grid, {10, 10}, kLevel);
  f.seam = {grid.cell_from_point({-0.3, 5}, kLevel), grid.cell_from_point({0.3, 5}, kLevel)};

  auto store = Store::open(f.store_path, Store::Mode::Create);
  LayerInfo dem = layer_info("dem", DType::F32, 1, kTileSize, kLevel);
  dem.nodata = -9999;
  dem.units = "m";
  const LayerInfo rgb = layer_info("rgb", DType::U8, 3, kTileSize, kLevel);
  store->create_layer(dem);
  store->create_layer(rgb);
  Store::Batch batch(*store);
  std::vector<CellId> all = f.block;
  all.insert(all.end(), f.seam.begin(), f.seam.end());
  for (CellId c : all) {
    batch.put_tile("dem", c, dem_tile(grid, c));
    batch.put_tile(
        "rgb", c, make_tile<uint8_t>(grid, c, kTileSize, 3, [](const TileSample& s, int k) {
          return uint8_t(int(std::abs(s.lonlat.lon * 50 + s.lonlat.lat * 30 + k * 60)) % 256);
        }));
  }
  batch.commit();
  store->update_overviews("dem");
  store->update_overviews("rgb");
  return f;
}

}  // namespace

std::string corner_store(const std::vector<CellId>& cells) {
  const Grid& grid = default_grid();
  const std::string path = temp_dir() + "/corner.maquette";
  auto store = Store::open(path, Store::Mode::Create);
  LayerInfo dem = layer_info("dem", DType::F32, 1, kTileSize, cells.front().level());
  dem.units = "m";
  store->create_layer(dem);
  Store::Batch batch(*store);
  for (CellId c : cells) batch.put_tile("dem", c, dem_tile(grid, c));
  batch.commit();
  return path;
}

const Tiles3dFixture& tiles3d_fixture() {
  static const Tiles3dFixture f = build();
  return f;
}

double dem_field(LonLat p) {
  return 1000.0 + 500.0 * std::sin(p.lon * M_PI / 9) * std::cos(p.lat * M_PI / 12);
}

}  // namespace maquette::test
