// Basins shared by the deform.water tests and benchmark: an analytic paraboloid and a bowl of
// hills, which r.lake reads as a GeoTIFF.
#pragma once

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "../water_body.h"

namespace maquette::deform {

// A raster of `width` x `height` pixels of `pixel_m` metres with its stroke's mask.
struct Basin {
  int width = 0, height = 0;
  double pixel_m = 1;
  std::vector<float> terrain;
  std::vector<uint8_t> inside;
  BasinRaster raster() const { return {width, height, terrain, inside, pixel_m * pixel_m}; }
};

// The paraboloid z = (x^2 + y^2) / 1000 (metres, centred) inside a disk of radius 450 m.
inline Basin paraboloid() {
  Basin b{1000, 1000, 1.0, {}, {}};
  for (int r = 0; r < b.height; ++r)
    for (int c = 0; c < b.width; ++c) {
      const double x = c + 0.5 - 500, y = r + 0.5 - 500;
      b.terrain.push_back(float((x * x + y * y) / 1000));
      b.inside.push_back(x * x + y * y <= 450.0 * 450.0);
    }
  return b;
}

// A `width` x `height` DEM of 30 m pixels, placed at (kX0, kY0) in UTM zone 12 when written as a
// GeoTIFF for r.lake: a bowl with hills and islands, the stroke an ellipse.
constexpr double kX0 = 300000, kY0 = 4100000, kPixelM = 30;
inline Basin hills(int width = 600, int height = 500) {
  Basin b{width, height, kPixelM, {}, {}};
  for (int r = 0; r < b.height; ++r)
    for (int c = 0; c < b.width; ++c) {
      const double x = (c + 0.5) * kPixelM, y = (r + 0.5) * kPixelM;
      const double u = (c - width / 2) / (0.42 * width), v = (r - height / 2) / (0.4 * height);
      b.terrain.push_back(float(1000 + 60 * (u * u + v * v) +
                                15 * std::sin(x / 300) * std::cos(y / 410) +
                                8 * std::sin((x + 2 * y) / 170)));
      b.inside.push_back(u * u + v * v <= 1);
    }
  return b;
}

// Writes `b` (a hills() basin) as a Float32 GeoTIFF at (kX0, kY0) in UTM zone 12; false when
// GDAL fails.
inline bool write_geotiff(const Basin& b, const std::string& path) {
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      path.c_str(), b.width, b.height, 1, GDT_Float32, nullptr));
  if (!ds) return false;
  double transform[6] = {kX0, b.pixel_m, 0, kY0, 0, -b.pixel_m};
  ds->SetGeoTransform(transform);
  OGRSpatialReference srs;
  srs.importFromEPSG(32612);
  ds->SetSpatialRef(&srs);
  return ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, b.width, b.height,
                                        const_cast<float*>(b.terrain.data()), b.width, b.height,
                                        GDT_Float32, 0, 0) == CE_None;
}

}  // namespace maquette::deform
