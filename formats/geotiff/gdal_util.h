// Small GDAL helpers shared by the GeoTIFF writers.
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>

#include "core/tile.h"
#include "gdal/gdal_env.h"  // GdalSession, gdal_error

namespace maquette {

GDALDataType gdal_type(DType t);

struct GdalClose {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, GdalClose>;

// Creation options of every GeoTIFF we write: 256 x 256 tiles, DEFLATE with the predictor
// that suits the samples (floating point or integer), BigTIFF when needed, and unwritten (empty)
// tiles left sparse (GDAL reads them as nodata).
CPLStringList geotiff_creation_options(bool floating_point);

}  // namespace maquette
