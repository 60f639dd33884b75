// The CRS an export writes: the rHEALPix plane of the grid, or an EPSG CRS.
#pragma once

#include <ogr_spatialref.h>

#include <string>

namespace maquette {

// rHEALPix on WGS84 as the grid uses it. GeoTIFF has no keys for it, so GDAL keeps it (as WKT
// with this PROJ string) in the OUT.tif.aux.xml file beside the image.
inline constexpr const char* kRHealpixProj =
    "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0 +units=m +no_defs";

struct ExportCrs {
  bool rhealpix = true;
  OGRSpatialReference srs;  // traditional GIS axis order (x = easting or longitude)
};

// "rhealpix" or "EPSG:NNNN" (case-insensitive prefix); throws maquette::Error naming the value.
ExportCrs parse_export_crs(const std::string& text);

// The CRS as errors name it: "EPSG:NNNN", or else its name.
std::string crs_name(const OGRSpatialReference& srs);

}  // namespace maquette
