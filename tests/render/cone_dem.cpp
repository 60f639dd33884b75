#include "cone_dem.h"

#include <algorithm>
#include <cmath>

#include "synthetic_raster.h"

namespace maquette::test {

std::array<double, 2> cone_axis() {
  return Projector("EPSG:4326", "EPSG:32612")(kConeLon, kConeLat);
}

double cone_height(double e, double n) {
  return kConeBase + kConeHeight * std::max(0.0, 1 - std::hypot(e, n) / kConeRadius);
}

std::string write_utm_dem(const std::string& path, int cells, double cell,
                          const std::function<double(double, double)>& height) {
  const auto [x, y] = cone_axis();
  RasterSpec spec;
  spec.width = spec.height = cells;
  const double half = cells * cell / 2;
  spec.geotransform = {x - half, cell, 0, y + half, 0, -cell};
  spec.crs = "EPSG:32612";
  write_raster(path, spec,
               [x = x, y = y, &height](int, double e, double n) { return height(e - x, n - y); });
  return path;
}

}  // namespace maquette::test
