// Opening OGR vector sources and transforming their layers to WGS84 lon/lat.
#pragma once

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <memory>
#include <string>

namespace maquette {

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using VectorDataset = std::unique_ptr<GDALDataset, DatasetCloser>;

// Opens `path` read-only as a vector source; throws maquette::Error naming it (with GDAL's
// reason) when it is missing, unreadable or holds no vector layer.
VectorDataset open_vector(const std::string& path);

// The transformation of `layer`'s geometries to WGS84 lon/lat (x = longitude, y = latitude,
// whatever the CRS's axis order). `src_crs` (any string OGRSpatialReference::SetFromUserInput
// takes) overrides the layer's CRS; a layer without a CRS and no `src_crs` is refused with an
// error naming `source` and the layer.
std::unique_ptr<OGRCoordinateTransformation> lonlat_transform(OGRLayer& layer,
                                                              const std::string& source,
                                                              const std::string& src_crs);

}  // namespace maquette
