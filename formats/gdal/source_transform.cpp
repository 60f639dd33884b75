#include "gdal/source_transform.h"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <string>
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

// Creating a transformation searches PROJ's database (~2-4 ms, a tenth of a small ingest's CPU
// with one per thread and per planning step); cloning or inverting one does not. So one pair per
// CRS, made once and cloned by every SourceTransform (each thread needs its own).
struct Transforms {
  std::unique_ptr<OGRCoordinateTransformation> forward, backward;
};
Transforms cloned_transforms(const RasterSource& source) {
  const std::string& crs_wkt = source.crs_wkt;
  static std::mutex mutex;
  // Never destroyed: destroying PROJ objects after PROJ's own teardown at exit would crash.
  static auto& prototypes = *new std::map<std::string, Transforms>();
  const std::lock_guard lock(mutex);
  auto it = prototypes.find(crs_wkt);
  if (it == prototypes.end()) {
    OGRSpatialReference wgs84, src(*source.crs);
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    // The forward one as the backward one's inverse: the same operation run the other way,
    // without a second search of the database.
    Transforms t;
    t.backward.reset(OGRCreateCoordinateTransformation(&src, &wgs84));
    if (!t.backward) return {};
    t.forward.reset(t.backward->GetInverse());
    if (!t.forward) return {};
    it = prototypes.emplace(crs_wkt, std::move(t)).first;
  }
  return {std::unique_ptr<OGRCoordinateTransformation>(it->second.forward->Clone()),
          std::unique_ptr<OGRCoordinateTransformation>(it->second.backward->Clone())};
}

}  // namespace

SourceTransform::SourceTransform(const RasterSource& source) : source_(source) {
  Transforms t = cloned_transforms(source);
  forward_ = std::move(t.forward);
  backward_ = std::move(t.backward);
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
