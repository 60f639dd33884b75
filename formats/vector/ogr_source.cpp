#include "vector/ogr_source.h"

#include <cpl_error.h>

#include "core/error.h"
#include "core/file_access.h"
#include "gdal/gdal_drivers.h"

namespace maquette {
namespace {

std::string gdal_reason() {
  const std::string msg = CPLGetLastErrorMsg();
  return msg.empty() ? "" : ": " + msg;
}

}  // namespace

VectorDataset open_vector(const std::string& path) {
  register_all_gdal_drivers();
  CPLErrorReset();
  VectorDataset ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds) {
    if (const auto problem = file_access_problem(path))
      throw Error("cannot open " + path + ": " + *problem);
    throw Error("cannot open " + path + ": not a vector format GDAL reads" + gdal_reason());
  }
  if (ds->GetLayerCount() == 0) throw Error(path + " holds no vector layer");
  return ds;
}

std::unique_ptr<OGRCoordinateTransformation> lonlat_transform(OGRLayer& layer,
                                                              const std::string& source,
                                                              const std::string& src_crs) {
  const std::string where = source + " layer '" + layer.GetName() + "'";
  OGRSpatialReference src;
  if (!src_crs.empty()) {
    if (src.SetFromUserInput(src_crs.c_str()) != OGRERR_NONE)
      throw Error("--src-crs '" + src_crs + "' is not a CRS GDAL knows");
  } else if (const OGRSpatialReference* own = layer.GetSpatialRef()) {
    src = *own;
  } else {
    throw Error(where + " has no CRS: give the source CRS (--src-crs EPSG:NNNN)");
  }
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  CPLErrorReset();
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&src, &wgs84));
  if (!ct) throw Error(where + ": no transformation from its CRS to WGS84" + gdal_reason());
  return ct;
}

}  // namespace maquette
