#include "export_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "run_cli.h"
#include "test_tiles.h"

namespace maquette::test {
namespace {

LayerInfo layer(const std::string& name, DType dtype, int channels) {
  return layer_info(name, dtype, channels, kTileSize, kLevel);
}

ExportFixture build() {
  GDALAllRegister();
  const Grid& grid = default_grid();
  ExportFixture f;
  f.store_path = temp_dir() + "/export.maquette";
  f.dem_cells = block_of_four(grid, {10, 10}, kLevel);
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
    batch.put_tile("dem", c, make_tile<float>(grid, c, kTileSize, 1, [](const TileSample& s, int) {
                     return dem_field(s.plane);
                   }));
    batch.put_tile("landcover", c,
                   make_tile<uint8_t>(grid, c, kTileSize, 1, [](const TileSample& s, int) {
                     return landcover_class(s.col, s.row);
                   }));
    // Pseudo-random bytes, roughly uniform in 0..199 in every band.
    batch.put_tile(
        "rgb", c, make_tile<uint8_t>(grid, c, kTileSize, 3, [](const TileSample& s, int k) {
          return uint8_t(((s.col * 7919 + s.row * 104729 + k * 31) * 2654435761LL >> 7) % 200);
        }));
  }
  for (CellId c : f.twofaces_cells)
    batch.put_tile("twofaces", c,
                   make_tile<float>(grid, c, kTileSize, 1, [c](const TileSample& s, int) {
                     return float(c.face() * 1000 + s.col % 100 + 0.5 * (s.row % 7));
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

std::string export_layer(const std::string& format, const std::string& layer,
                         const std::string& extension, const std::string& extra) {
  const std::string out = temp_dir() + "/" + layer + "." + extension;
  const CliResult r = run_maquette("export " + format + " " + export_fixture().store_path +
                                   " --layer " + layer + " " + out + " " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return out;
}

Dataset open_raster(const std::string& path) {
  GDALAllRegister();
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
