// maquette export gtiff: a layer (or a region of it, at its level or an overview level) as a
// tiled, compressed GeoTIFF in the rHEALPix plane or resampled to an EPSG CRS.
#pragma once

#include <optional>
#include <string>

#include "core/grid.h"
#include "image/layer_cells.h"
#include "store/store.h"

namespace maquette {

struct GeoTiffExport {
  std::string layer;
  RegionSpec region;
  std::optional<int> level;              // default: the layer's level; coarser reads overviews
  std::string crs = "rhealpix";          // or "EPSG:NNNN"
  std::optional<double> resolution;      // target CRS units; default: the layer pixel at the centre
  int64_t max_bytes = int64_t(4) << 30;  // refuse larger exports (uncompressed) unless forced
  bool force = false;
};

// Writes `out` (and out.aux.xml, which holds what GeoTIFF cannot: the rHEALPix CRS, class
// names). With a box the output covers the box (on whole pixels in the rHEALPix plane); without
// one, the region's cells (in a geographic CRS up to the poles they hold). Refuses, with an
// estimate, an output whose uncompressed size is above max_bytes unless forced. Nothing is left at
// `out` when it fails: the files are written under a temporary name and renamed at the end. Throws
// maquette::Error.
void export_geotiff(const Store& store, const Grid& grid, const GeoTiffExport& spec,
                    const std::string& out);

}  // namespace maquette
