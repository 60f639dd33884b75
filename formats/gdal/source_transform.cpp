#include "gdal/source_transform.h"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"

namespace maquette {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void apply(const std::array<double, 6>& gt, double& x, double& y) {
  const double u = gt[0] + x * gt[1] + y * gt[2];
  const double v = gt[3] + x * gt[4] + y * gt[5];
  x = u;
  y = v;
}

}  // namespace

SourceTransform::SourceTransform(const RasterSource& source) : source_(source) {
  OGRSpatialReference wgs84, src(source.crs_wkt.c_str());
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  forward_.reset(OGRCreateCoordinateTransformation(&wgs84, &src));
  backward_.reset(OGRCreateCoordinateTransformation(&src, &wgs84));
  if (!forward_ || !backward_)
    throw Error(source.path + ": no transformation between its CRS and WGS84 lon/lat");
  const auto& gt = source.geotransform;
  west_ = std::min({gt[0], gt[0] + source.width * gt[1], gt[0] + source.height * gt[2],
                    gt[0] + source.width * gt[1] + source.height * gt[2]});
}

SourceTransform::~SourceTransform() = default;

void SourceTransform::to_pixel(std::span<double> x, std::span<double> y) const {
  std::vector<int> ok(x.size());
  forward_->Transform(x.size(), x.data(), y.data(), nullptr, ok.data());
  for (size_t i = 0; i < x.size(); ++i) {
    if (!ok[i] || !std::isfinite(x[i]) || !std::isfinite(y[i])) {
      x[i] = y[i] = kNaN;
      continue;
    }
    if (source_.geographic) x[i] = west_ + std::fmod(std::fmod(x[i] - west_, 360.0) + 360.0, 360.0);
    apply(source_.inverse, x[i], y[i]);
  }
}

void SourceTransform::to_lonlat(std::span<double> x, std::span<double> y) const {
  for (size_t i = 0; i < x.size(); ++i) apply(source_.geotransform, x[i], y[i]);
  std::vector<int> ok(x.size());
  backward_->Transform(x.size(), x.data(), y.data(), nullptr, ok.data());
  for (size_t i = 0; i < x.size(); ++i)
    if (!ok[i] || !std::isfinite(x[i]) || !std::isfinite(y[i])) x[i] = y[i] = kNaN;
}

}  // namespace maquette
