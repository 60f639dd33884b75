// A small store for the export tests, built once per test run: tiles with known values at known
// cells (64 x 64 samples, level 6, so pixels are at level 12).
//   dem        float32, metres, nodata -9999: a smooth field of the plane position, 2 x 2 cells
//   landcover  uint8 categorical, nodata 0, classes 1..3 with colours and names, same cells
//   twofaces   float32 without nodata: one cell on face P and one on face Q, not adjacent
//   rgb        uint8, 3 channels (imagery), same cells as dem
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>
#include <vector>

#include "core/grid.h"
#include "store/store.h"

namespace maquette::test {

inline constexpr int kTileSize = 64;
inline constexpr int kLevel = 6;
inline constexpr int kPixelLevel = 12;

struct ExportFixture {
  std::string store_path;
  std::vector<CellId> dem_cells;       // also landcover and rgb
  std::vector<CellId> twofaces_cells;  // P, then Q
};
const ExportFixture& export_fixture();

// The dem's value at a plane point (metres).
double dem_field(PlanePoint p);
// The landcover class at a face pixel (global col, row at kPixelLevel).
uint8_t landcover_class(int64_t col, int64_t row);

// Runs `maquette export FORMAT <the fixture's store> --layer LAYER OUT EXTRA`, OUT a file
// LAYER.EXTENSION in a fresh directory, expecting success; returns OUT.
std::string export_layer(const std::string& format, const std::string& layer,
                         const std::string& extension, const std::string& extra = "");

struct GdalClose {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using Dataset = std::unique_ptr<GDALDataset, GdalClose>;
Dataset open_raster(const std::string& path);  // GDAL open (read-only); nullptr when it fails

// Band 1 of a dataset as doubles, row-major.
std::vector<double> read_band(GDALDataset& ds, int band = 1);

}  // namespace maquette::test
