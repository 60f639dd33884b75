// Basins shared by the deform.water tests: an analytic paraboloid and a bowl of hills.
#pragma once

#include <cmath>
#include <cstdint>
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

}  // namespace maquette::deform
