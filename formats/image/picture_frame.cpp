#include "image/picture_frame.h"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/lonlat_bounds.h"
#include "core/region.h"

namespace maquette {
namespace {

constexpr double kMetresPerDegree = 111319.49;  // at the equator, to pick a pixel size
constexpr int kBoxLattice = 129;                // points per side of a box projected for the extent

std::string laea_proj(Projection p) {
  return std::string("+proj=laea +lat_0=") + (p == Projection::NorthPolar ? "90" : "-90") +
         " +lon_0=0 +datum=WGS84 +units=m +no_defs";
}

OGRSpatialReference srs_of(Projection p) {
  OGRSpatialReference srs;
  if (p == Projection::LonLat)
    srs.importFromEPSG(4326);
  else
    srs.importFromProj4(laea_proj(p).c_str());
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

std::shared_ptr<OGRCoordinateTransformation> transformation(Projection from, Projection to) {
  const OGRSpatialReference a = srs_of(from), b = srs_of(to);
  std::shared_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&a, &b),
                                                 OGRCoordinateTransformation::DestroyCT);
  if (!t) throw Error("PROJ cannot transform between lon/lat and " + laea_proj(to));
  return t;
}

// Points along the region's outline (box edges or cell boundaries) and the poles it holds.
struct Outline {
  std::vector<LonLat> points;
  bool north_pole = false, south_pole = false;
  double west = 0, south = 0, east = 0, north = 0;  // east may exceed 180 (antimeridian)
};

Outline outline_of(const Grid& grid, const PictureRegion& region) {
  Outline o;
  if (region.bbox) {
    const auto& b = *region.bbox;
    return {bbox_points(b, kBoxLattice),         b[3] >= 90.0, b[1] <= -90.0, b[0], b[1],
            b[2] + (b[2] <= b[0] ? 360.0 : 0.0), b[3]};
  }
  if (region.cells.empty()) throw Error("a picture needs a region");
  const LonLatBounds b = lonlat_bounds(grid, region.cells);
  o.west = b.west, o.south = b.south, o.east = b.east, o.north = b.north;
  o.north_pole = o.north >= 90, o.south_pole = o.south <= -90;
  for (CellId c : compact(region.cells)) {
    const std::vector<LonLat> ring = grid.boundary(c, 8);
    o.points.insert(o.points.end(), ring.begin(), ring.end());
  }
  return o;
}

Projection choose_projection(const Outline& o) {
  if (o.north_pole != o.south_pole) {
    if (o.north_pole && o.south >= 0) return Projection::NorthPolar;
    if (o.south_pole && o.north <= 0) return Projection::SouthPolar;
  } else if (!o.north_pole && o.east - o.west > 90) {
    if (o.south >= 60) return Projection::NorthPolar;
    if (o.north <= -60) return Projection::SouthPolar;
  }
  return Projection::LonLat;
}

// Pixels of `step`, or larger so that both spans fit max_side, then stretched a little per axis
// so that whole pixels cover the spans exactly. `doublings`: how many times the pixel doubled
// (rounded down), so that overviews that many levels up are at least as fine.
void fit_pixels(PictureFrame& f, double x_span, double y_span, double step, int max_side,
                int& doublings) {
  const double fitted = std::max(step, std::max(x_span, y_span) / max_side);
  doublings = int(std::floor(std::log2(fitted / step) + 1e-9));
  auto count = [&](double span) { return std::max(1, int(std::ceil(span / fitted - 1e-9))); };
  f.width = count(x_span), f.height = count(y_span);
  f.x_step = x_span > 0 ? x_span / f.width : fitted;
  f.y_step = y_span > 0 ? y_span / f.height : fitted;
}

}  // namespace

Projection parse_projection(std::string_view name) {
  if (name == "auto") return Projection::Auto;
  if (name == "lonlat") return Projection::LonLat;
  if (name == "polar") return Projection::NorthPolar;  // the pole is chosen by frame_for
  throw Error("unknown projection '" + std::string(name) + "' (expected auto, lonlat or polar)");
}

std::array<double, 6> PictureFrame::geotransform() const {
  return {left, x_step, 0, top, 0, -y_step};
}

std::string PictureFrame::crs_wkt() const {
  char* wkt = nullptr;
  srs_of(projection).exportToWkt(&wkt);
  std::string out = wkt ? wkt : "";
  CPLFree(wkt);
  return out;
}

std::string PictureFrame::crs_name() const {
  switch (projection) {
    case Projection::NorthPolar:
      return "north polar LAEA";
    case Projection::SouthPolar:
      return "south polar LAEA";
    default:
      return "lon/lat";
  }
}

PictureFrame frame_for(const Grid& grid, const PictureRegion& region, Projection projection,
                       double pixel_m, int max_side, int& doublings) {
  const Outline o = outline_of(grid, region);
  PictureFrame f;
  f.projection = projection == Projection::Auto ? choose_projection(o) : projection;
  if (projection == Projection::NorthPolar && o.south_pole && !o.north_pole)
    f.projection = Projection::SouthPolar;  // "polar": the pole the region is around
  if (f.projection == Projection::LonLat) {
    f.left = o.west, f.top = o.north;
    fit_pixels(f, o.east - o.west, o.north - o.south, pixel_m / kMetresPerDegree, max_side,
               doublings);
    return f;
  }
  std::vector<double> x, y;
  for (const LonLat& p : o.points) x.push_back(p.lon), y.push_back(p.lat);
  if (o.north_pole || o.south_pole)
    x.push_back(0), y.push_back(f.projection == Projection::NorthPolar ? 90 : -90);
  if (!transformation(Projection::LonLat, f.projection)->Transform(x.size(), x.data(), y.data()))
    throw Error("PROJ cannot project the region's outline to " + laea_proj(f.projection));
  const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
  const auto [y0, y1] = std::minmax_element(y.begin(), y.end());
  f.left = *x0, f.top = *y1;
  fit_pixels(f, *x1 - *x0, *y1 - *y0, pixel_m, max_side, doublings);
  return f;
}

FramePixels::FramePixels(const PictureFrame& frame) : frame_(frame) {
  if (frame.projection != Projection::LonLat)
    to_lonlat_ = transformation(frame.projection, Projection::LonLat);
}

void FramePixels::row(int row, std::vector<LonLat>& out) const {
  const PictureFrame& f = frame_;
  out.resize(size_t(f.width));
  const double y = f.top - (row + 0.5) * f.y_step;
  if (!to_lonlat_) {
    for (int c = 0; c < f.width; ++c)
      out[size_t(c)] = {std::remainder(f.left + (c + 0.5) * f.x_step, 360.0), y};
    return;
  }
  std::vector<double> xs(out.size()), ys(out.size(), y);
  for (int c = 0; c < f.width; ++c) xs[size_t(c)] = f.left + (c + 0.5) * f.x_step;
  std::vector<int> ok(out.size());
  to_lonlat_->Transform(xs.size(), xs.data(), ys.data(), nullptr, ok.data());
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  for (size_t c = 0; c < out.size(); ++c)
    out[c] = ok[c] && std::abs(ys[c]) <= 90 ? LonLat{xs[c], ys[c]} : LonLat{nan, nan};
}

std::vector<LonLat> bbox_points(const std::array<double, 4>& b, int n) {
  const double east = b[2] + (b[2] <= b[0] ? 360.0 : 0.0);
  std::vector<LonLat> points;
  points.reserve(size_t(n) * size_t(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      points.push_back({b[0] + (east - b[0]) * j / (n - 1), b[1] + (b[3] - b[1]) * i / (n - 1)});
  return points;
}

bool in_bbox(const std::array<double, 4>& b, LonLat p) {
  if (!(p.lat >= b[1] && p.lat <= b[3])) return false;
  const double east = b[2] + (b[2] <= b[0] ? 360.0 : 0.0);
  const double lon = b[0] + std::fmod(std::fmod(p.lon - b[0], 360.0) + 360.0, 360.0);
  return lon <= east || (east - b[0] >= 360.0);
}

}  // namespace maquette
