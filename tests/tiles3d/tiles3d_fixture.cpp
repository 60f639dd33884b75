#include "tiles3d_fixture.h"

#include <cmath>

#include "gltf/content_layer.h"
#include "run_cli.h"
#include "store/store.h"
#include "test_tiles.h"

namespace maquette::test {
namespace {

RawTile dem_tile(const Grid& grid, CellId cell) {
  return make_tile<float>(grid, cell, kTileSize, 1,
                          [](const TileSample& s, int) { return dem_field(s.lonlat); });
}

LonLat centre(const Grid& grid, CellId cell) {
  const PlaneSquare sq = grid.plane_square(cell);
  return grid.inverse({sq.x_min + sq.side / 2, sq.y_max - sq.side / 2});
}

// A 100 m box standing on the terrain at the cell's centre (8 corners, 12 triangles).
ContentTile box_content(const Grid& grid, CellId cell) {
  const LonLat c = centre(grid, cell);
  const double dlat = 50 / 111320.0, dlon = dlat / std::cos(c.lat * M_PI / 180);
  ContentTile box;
  for (int i = 0; i < 8; ++i)
    box.positions.insert(box.positions.end(),
                         {c.lon + (i & 1 ? dlon : -dlon), c.lat + (i & 4 ? -dlat : dlat),
                          dem_field(c) + (i & 2 ? 100 : 0)});
  box.indices = {0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2,
                 1, 3, 7, 1, 7, 5, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  box.color = {0.8, 0.3, 0.2};
  return box;
}

ContentTile tree_content(const Grid& grid, CellId cell) {
  const LonLat c = centre(grid, cell);
  ContentTile trees;
  trees.kind = ContentTile::Kind::Instances;
  trees.prototype = "cone";
  trees.color = {0.2, 0.5, 0.2};
  for (int i = 0; i < kTreeCount; ++i) {
    const LonLat p{c.lon + 0.01 * i, c.lat - 0.01 * i};
    trees.instances.push_back({p.lon, p.lat, dem_field(p), 20.0 + i, 30.0 * i});
  }
  return trees;
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
  put_content(batch, "boxes", f.block[0], box_content(grid, f.block[0]));
  put_content(batch, "trees", f.block[1], tree_content(grid, f.block[1]));
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
