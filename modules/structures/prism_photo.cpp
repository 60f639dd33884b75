#include "prism_photo.h"

#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "core/error.h"

namespace maquette::structures {
namespace {

// An EXIF rational as GDAL gives it: "(35)" or "35" or "(4.2)".
std::optional<double> number(const char* text) {
  if (!text) return std::nullopt;
  std::string s(text);
  s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == '(' || c == ')'; }), s.end());
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || !std::isfinite(v) || v <= 0) return std::nullopt;
  return v;
}

}  // namespace

std::optional<double> exif_focal_px(GDALDataset& photo) {
  GDALDataset* ds = &photo;
  if (const auto f35 = number(ds->GetMetadataItem("EXIF_FocalLengthIn35mmFilm")))
    return *f35 * std::hypot(ds->GetRasterXSize(), ds->GetRasterYSize()) / kFullFrameDiagonalMm;
  const auto mm = number(ds->GetMetadataItem("EXIF_FocalLength"));
  const auto per_unit = number(ds->GetMetadataItem("EXIF_FocalPlaneXResolution"));
  const auto unit = number(ds->GetMetadataItem("EXIF_FocalPlaneResolutionUnit"));
  if (mm && per_unit && unit && (*unit == 2 || *unit == 3)) {
    const auto sensor_width = number(ds->GetMetadataItem("EXIF_PixelXDimension"));
    const double resized = sensor_width ? ds->GetRasterXSize() / *sensor_width : 1.0;
    return *mm * *per_unit / (*unit == 2 ? 25.4 : 10.0) * resized;
  }
  return std::nullopt;
}

Photo read_photo(const std::string& path) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) throw Error(path + ": GDAL cannot open the photo");
  const int bands = ds->GetRasterCount(), width = ds->GetRasterXSize(),
            height = ds->GetRasterYSize();
  if (bands != 1 && bands != 3 && bands != 4)
    throw Error(path + ": a photo has 1 (grey), 3 or 4 (RGB, alpha) bands, not " +
                std::to_string(bands));
  const int channels = bands == 1 ? 1 : 3;
  Photo photo;
  photo.pixels.create(height, width, channels == 1 ? CV_8UC1 : CV_8UC3);
  // BGR: band 3 into channel 0, band 1 into channel 2, interleaved by the pixel spacing.
  std::vector<int> band_map;
  for (int c = 0; c < channels; ++c) band_map.push_back(channels == 1 ? 1 : 3 - c);
  if (ds->RasterIO(GF_Read, 0, 0, width, height, photo.pixels.data, width, height, GDT_Byte,
                   channels, band_map.data(), channels, long(photo.pixels.step), 1,
                   nullptr) != CE_None)
    throw Error(path + ": GDAL cannot read the photo's pixels");
  // A phone's photo may be stored on its side with a tag to turn it: the clicks are on the
  // turned picture, the pixels here are not.
  if (const char* o = ds->GetMetadataItem("EXIF_Orientation"); o && number(o) != 1.0)
    throw Error(path + ": EXIF_Orientation " + o +
                ": the photo is shown turned or mirrored; turn its pixels upright first (e.g. "
                "exiftran -ai) and click on them");
  photo.focal_px = exif_focal_px(*ds);
  return photo;
}

double prior_focal_px(int width, int height) { return std::hypot(width, height); }

}  // namespace maquette::structures
