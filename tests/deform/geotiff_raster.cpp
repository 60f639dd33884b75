#include "geotiff_raster.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <memory>

namespace maquette::test {

Raster read_raster(const std::string& path) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(ds) << path;
  Raster r;
  if (!ds) return r;
  r.width = ds->GetRasterXSize();
  r.height = ds->GetRasterYSize();
  ds->GetGeoTransform(r.transform.data());
  if (const char* wkt = ds->GetProjectionRef()) r.crs_wkt = wkt;
  r.values.resize(size_t(r.width) * size_t(r.height));
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, r.width, r.height, r.values.data(),
                                           r.width, r.height, GDT_Float32, 0, 0),
            CE_None);
  return r;
}

}  // namespace maquette::test
