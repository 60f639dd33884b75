#include "geotiff/warp.h"

#include <gdal_utils.h>

#include <memory>

#include "core/error.h"
#include "geotiff/gdal_util.h"

namespace maquette {

void warp_geotiff(const std::string& src, const std::string& dst, const WarpSpec& spec) {
  DatasetPtr in(GDALDataset::Open(src.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!in) gdal_error("cannot read " + src);
  const GDALDataType type = in->GetRasterBand(1)->GetRasterDataType();

  char* wkt = nullptr;
  spec.crs->exportToWkt(&wkt);
  const std::string target_wkt = wkt;
  CPLFree(wkt);
  const std::string res = CPLSPrintf("%.17g", spec.resolution);
  CPLStringList args;
  for (const char* a : {"-of", "GTiff", "-t_srs", target_wkt.c_str(), "-tr", res.c_str(),
                        res.c_str(), "-r", spec.nearest ? "near" : "bilinear", "-et", "0"})
    args.AddString(a);
  if (spec.bbox_lonlat && (*spec.bbox_lonlat)[0] < (*spec.bbox_lonlat)[2]) {
    args.AddString("-te");
    for (double v : *spec.bbox_lonlat) args.AddString(CPLSPrintf("%.17g", v));
    for (const char* a : {"-te_srs", "EPSG:4326"}) args.AddString(a);
  }
  const CPLStringList options = geotiff_creation_options(GDALDataTypeIsFloating(type));
  for (int i = 0; i < options.Count(); ++i) {
    args.AddString("-co");
    args.AddString(options[i]);
  }
  std::unique_ptr<GDALWarpAppOptions, decltype(&GDALWarpAppOptionsFree)> warp_options(
      GDALWarpAppOptionsNew(args.List(), nullptr), GDALWarpAppOptionsFree);
  if (!warp_options) gdal_error("bad warp options");
  GDALDatasetH source = GDALDataset::ToHandle(in.get());
  int usage_error = 0;
  DatasetPtr out(GDALDataset::FromHandle(
      GDALWarp(dst.c_str(), nullptr, 1, &source, warp_options.get(), &usage_error)));
  if (!out || usage_error) gdal_error("cannot warp to " + dst);
  out.reset();
  if (CPLGetLastErrorType() == CE_Failure) gdal_error("cannot write " + dst);
}

}  // namespace maquette
