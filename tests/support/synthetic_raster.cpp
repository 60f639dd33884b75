#include "synthetic_raster.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace maquette::test {
struct Projector::Impl {
  std::unique_ptr<OGRCoordinateTransformation> t;
};

Projector::Projector(const std::string& from, const std::string& to) : impl_(new Impl) {
  OGRSpatialReference a, b;
  a.SetFromUserInput(from.c_str());
  b.SetFromUserInput(to.c_str());
  a.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  b.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  impl_->t.reset(OGRCreateCoordinateTransformation(&a, &b));
  if (!impl_->t) throw std::runtime_error("no transformation " + from + " -> " + to);
}

Projector::~Projector() = default;

std::array<double, 2> Projector::operator()(double x, double y) const {
  if (!impl_->t->Transform(1, &x, &y)) return {NAN, NAN};
  return {x, y};
}

std::string write_png(const std::string& path, int width, int height, int bands,
                      const std::function<double(int x, int y, int band)>& value) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> mem(GetGDALDriverManager()->GetDriverByName("MEM")->Create(
      "", width, height, bands, GDT_Byte, nullptr));
  std::vector<uint8_t> band(size_t(width) * size_t(height));
  for (int b = 0; b < bands; ++b) {
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        band[size_t(y) * size_t(width) + size_t(x)] =
            uint8_t(std::clamp(std::lround(value(x, y, b)), 0L, 255L));
    if (mem->GetRasterBand(b + 1)->RasterIO(GF_Write, 0, 0, width, height, band.data(), width,
                                            height, GDT_Byte, 0, 0) != CE_None)
      throw std::runtime_error("write failed: " + path);
  }
  GDALDataset* png = GetGDALDriverManager()->GetDriverByName("PNG")->CreateCopy(
      path.c_str(), mem.get(), false, nullptr, nullptr, nullptr);
  if (!png) throw std::runtime_error("cannot create " + path);
  GDALClose(png);
  return path;
}

void write_raster(const std::string& path, const RasterSpec& spec, const PixelValue& value) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  GDALDataset* ds = drv->Create(path.c_str(), spec.width, spec.height, spec.bands,
                                GDALGetDataTypeByName(spec.type.c_str()), nullptr);
  if (!ds) throw std::runtime_error("cannot create " + path);
  auto gt = spec.geotransform;
  ds->SetGeoTransform(gt.data());
  if (!spec.crs.empty()) {
    OGRSpatialReference srs;
    srs.SetFromUserInput(spec.crs.c_str());
    ds->SetSpatialRef(&srs);
  }
  std::vector<double> row(size_t(spec.width));
  for (int b = 1; b <= spec.bands; ++b) {
    GDALRasterBand* band = ds->GetRasterBand(b);
    if (spec.nodata) band->SetNoDataValue(*spec.nodata);
    if (spec.scale != 1) band->SetScale(spec.scale);
    if (spec.offset != 0) band->SetOffset(spec.offset);
    for (int y = 0; y < spec.height; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        row[size_t(x)] = value(b, gt[0] + px * gt[1] + py * gt[2], gt[3] + px * gt[4] + py * gt[5]);
      }
      if (band->RasterIO(GF_Write, 0, y, spec.width, 1, row.data(), spec.width, 1, GDT_Float64, 0,
                         0) != CE_None)
        throw std::runtime_error("write failed");
    }
  }
  GDALRasterBand* first = ds->GetRasterBand(1);
  if (!spec.categories.empty()) {
    CPLStringList names;
    for (const auto& n : spec.categories) names.AddString(n.c_str());
    first->SetCategoryNames(names.List());
  }
  if (spec.colour_table) {
    GDALColorTable ct;
    for (int i = 0; i < 16; ++i) {
      const GDALColorEntry e{short(10 * i), short(20 * i), short(15 * i), 255};
      ct.SetColorEntry(i, &e);
    }
    first->SetColorTable(&ct);
  }
  GDALClose(ds);
}

RasterSpec lonlat_raster(double west, double north, int size, double pixel,
                         const std::string& type) {
  RasterSpec s;
  s.width = s.height = size;
  s.geotransform = {west, pixel, 0, north, 0, -pixel};
  s.crs = "EPSG:4326";
  s.type = type;
  return s;
}

double sphere_field(double lon, double lat) {
  constexpr double d = std::numbers::pi / 180;
  const double x = std::cos(lat * d) * std::cos(lon * d), y = std::cos(lat * d) * std::sin(lon * d),
               z = std::sin(lat * d);
  return 100 * (x + 2 * y + 3 * z);
}

}  // namespace maquette::test
