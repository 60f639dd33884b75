// Coordinates between WGS84 lon/lat (the grid's) and a source's pixel coordinates, through
// PROJ (OGRCoordinateTransformation). Not thread-safe: one per thread and source.
#pragma once

#include <memory>
#include <span>

#include "gdal/raster_source.h"

class OGRCoordinateTransformation;

namespace maquette {

class SourceTransform {
 public:
  explicit SourceTransform(const RasterSource& source);
  ~SourceTransform();
  SourceTransform(const SourceTransform&) = delete;
  SourceTransform& operator=(const SourceTransform&) = delete;

  // lon/lat (degrees) -> source pixel coordinates (x right, y down, pixel corners at integers),
  // in place; NaN where the transform fails. For geographic sources longitudes are first taken
  // into the source's own 360-degree range, so rasters across the antimeridian (lon 170..190)
  // and in 0..360 work.
  void to_pixel(std::span<double> x, std::span<double> y) const;
  // Source pixel coordinates -> lon/lat (degrees), in place; NaN where the transform fails.
  void to_lonlat(std::span<double> x, std::span<double> y) const;

 private:
  const RasterSource& source_;
  double west_ = 0;  // geographic sources: the smallest longitude of the raster
  std::unique_ptr<OGRCoordinateTransformation> forward_, backward_;
};

}  // namespace maquette
