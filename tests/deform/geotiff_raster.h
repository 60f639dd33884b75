// A single-band GeoTIFF read whole with GDAL, for tests that compare exported layers.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace maquette::test {

struct Raster {
  int width = 0, height = 0;
  std::array<double, 6> transform{};  // GDAL's geotransform
  std::string crs_wkt;
  std::vector<float> values;
  float at(int col, int row) const { return values[size_t(row) * size_t(width) + size_t(col)]; }
};

// Band 1 of `path` as float32; fails the current test (and returns an empty raster) when it
// cannot be read.
Raster read_raster(const std::string& path);

}  // namespace maquette::test
