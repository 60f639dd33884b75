// Resampling a GeoTIFF to another CRS with GDAL's warper (chunked: memory stays bounded).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "geotiff/export_crs.h"

namespace maquette {

struct WarpSpec {
  const OGRSpatialReference* crs = nullptr;
  double resolution = 0;                             // target units per pixel
  bool nearest = true;                               // else bilinear
  std::optional<std::array<double, 4>> bbox_lonlat;  // output extent; default: the source's
};

// Warps `src` to a new tiled, compressed GeoTIFF `dst` (same sample type and nodata). Each
// output pixel centre is transformed exactly (no approximating transformer), so nearest
// sampling picks the source pixel containing it. Throws maquette::Error.
void warp_geotiff(const std::string& src, const std::string& dst, const WarpSpec& spec);

}  // namespace maquette
