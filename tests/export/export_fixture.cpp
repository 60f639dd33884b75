#include "export_fixture.h"

#include <cmath>
#include <cstring>
#include <filesystem>

#include "run_cli.h"

namespace maquette::test {
namespace {

template <typename T, typename F>
RawTile make_tile(const Grid& grid, CellId cell, int channels, F value) {
  const PlaneSquare sq = grid.plane_square(cell);
  const double pixel = sq.side / kTileSize;
  std::vector<T> v;
  for (int r = 0; r < kTileSize; ++r)
    for (int c = 0; c < kTileSize; ++c)
      for (int k = 0; k < channels; ++k)
        v.push_back(T(value(PlanePoint{sq.x_min + (c + 0.5) * pixel, sq.y_max - (r + 0.5) * pixel},
                            global_col(cell, kTileSize, c), global_row(cell, kTileSize, r), k)));
  RawTile t{dtype_of<T>(), kTileSize, channels, std::vector<std::byte>(v.size() * sizeof(T))};
  std::memcpy(t.bytes.data(), v.data(), t.bytes.size());
  return t;
}

LayerInfo layer(const std::string& name, DType dtype, int channels) {
  LayerInfo info;
  info.name = name;
  info.dtype = dtype;
  info.channels = channels;
  info.tile_size = kTileSize;
  info.level = kLevel;
  return info;
}

ExportFixture build() {
  GDALAllRegister();
  const Grid& grid = default_grid();
  ExportFixture f;
  f.store_path = temp_dir() + "/export.maquette";
  const CellId parent = grid.cell_from_point({10, 10}, kLevel - 1);
  for (int d = 0; d < 4; ++d) f.dem_cells.push_back(parent.child(d));
  f.twofaces_cells = {grid.cell_from_point({-2, 5}, kLevel), grid.cell_from_point({3, 5}, kLevel)};

  auto store = Store::open(f.store_path, Store::Mode::Create);
  LayerInfo dem = layer("dem", DType::F32, 1);
  dem.nodata = -9999;
  dem.units = "m";
  LayerInfo lc = layer("landcover", DType::U8, 1);
  lc.nodata = 0;
  lc.semantics = Semantics::Categorical;
  lc.provenance["classes"] = {{"1", {{"name", "forest"}, {"color", "#228b22"}}},
                              {"2", {{"name", "water"}, {"color", "#1e90ff"}}},
                              {"3", {{"name", "urban"}, {"color", "#ff0000"}}}};
  const LayerInfo two = layer("twofaces", DType::F32, 1);
  const LayerInfo rgb = layer("rgb", DType::U8, 3);
  for (const LayerInfo& info : {dem, lc, two, rgb}) store->create_layer(info);

  Store::Batch batch(*store);
  for (CellId c : f.dem_cells) {
    batch.put_tile("dem", c, make_tile<float>(grid, c, 1, [](PlanePoint p, auto, auto, int) {
                     return dem_field(p);
                   }));
    batch.put_tile("landcover", c,
                   make_tile<uint8_t>(grid, c, 1, [](PlanePoint, int64_t col, int64_t row, int) {
                     return landcover_class(col, row);
                   }));
    // Pseudo-random bytes, roughly uniform in 0..199 in every band.
    batch.put_tile(
        "rgb", c, make_tile<uint8_t>(grid, c, 3, [](PlanePoint, int64_t col, int64_t row, int k) {
          return uint8_t(((col * 7919 + row * 104729 + k * 31) * 2654435761LL >> 7) % 200);
        }));
  }
  for (CellId c : f.twofaces_cells)
    batch.put_tile("twofaces", c,
                   make_tile<float>(grid, c, 1, [c](PlanePoint, int64_t col, int64_t row, int) {
                     return float(c.face() * 1000 + col % 100 + 0.5 * (row % 7));
                   }));
  batch.commit();
  store->update_overviews("dem");
  return f;
}

}  // namespace

const ExportFixture& export_fixture() {
  static const ExportFixture f = build();
  return f;
}

double dem_field(PlanePoint p) {
  return 1000.0 + 300.0 * std::sin(p.x / 40000.0) + 200.0 * std::cos(p.y / 55000.0);
}

uint8_t landcover_class(int64_t col, int64_t row) { return uint8_t((col / 9 + row / 7) % 3 + 1); }

Dataset open_raster(const std::string& path) {
  return Dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
}

std::vector<double> read_band(GDALDataset& ds, int band) {
  const int w = ds.GetRasterXSize(), h = ds.GetRasterYSize();
  std::vector<double> v(size_t(w) * size_t(h));
  if (ds.GetRasterBand(band)->RasterIO(GF_Read, 0, 0, w, h, v.data(), w, h, GDT_Float64, 0, 0) !=
      CE_None)
    v.clear();
  return v;
}

}  // namespace maquette::test
