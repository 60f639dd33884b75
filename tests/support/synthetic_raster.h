// Test rasters written with GDAL: a grid of pixels in some CRS filled by a function of each
// pixel centre's coordinates (in the raster's CRS, or lon/lat).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace maquette::test {

struct RasterSpec {
  int width = 0, height = 0, bands = 1;
  std::array<double, 6> geotransform{};
  std::string crs;               // "" for none
  std::string type = "Float32";  // GDAL type name
  std::optional<double> nodata;
  std::vector<std::string> categories;  // category names of band 1
  bool colour_table = false;            // a colour table on band 1 (class i: (10i, 20i, 15i))
  double scale = 1, offset = 0;         // of every band
};

// A north-up lon/lat (EPSG:4326) raster of size x size pixels of `pixel` degrees, its top-left
// corner at (west, north), of GDAL type `type`, no nodata.
RasterSpec lonlat_raster(double west, double north, int size, double pixel,
                         const std::string& type);

// value(band, x, y) with x, y the pixel centre in the raster's CRS.
using PixelValue = std::function<double(int band, double x, double y)>;

void write_raster(const std::string& path, const RasterSpec& spec, const PixelValue& value);

// An 8-bit PNG without georeferencing (a painting, a class image): `bands` bands of width x
// height, band b's pixel (x, y) value(x, y, b) rounded and clamped to 0..255 (b from 0), written
// through a MEM dataset copied by GDAL's PNG driver. Returns `path`.
std::string write_png(const std::string& path, int width, int height, int bands,
                      const std::function<double(int x, int y, int band)>& value);

// Transforms between two CRSs (traditional x/y order, e.g. "EPSG:4326" is lon, lat) with PROJ.
class Projector {
 public:
  Projector(const std::string& from, const std::string& to);
  ~Projector();
  std::array<double, 2> operator()(double x, double y) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A smooth field on the sphere: the unit vector of (lon, lat) dotted with (1, 2, 3), times 100.
double sphere_field(double lon, double lat);

}  // namespace maquette::test
