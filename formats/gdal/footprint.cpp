#include "gdal/footprint.h"

#include <ogr_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>

#include "core/error.h"
#include "gdal/source_transform.h"

namespace maquette {
namespace {

constexpr int kEdgePoints = 64;
constexpr double kA = 6378137.0, kE2 = 6.69437999014e-3;  // WGS84

// Whether lon/lat `p` falls inside the raster.
bool inside(const SourceTransform& t, const RasterSource& s, LonLat p) {
  double x = p.lon, y = p.lat;
  t.to_pixel({&x, 1}, {&y, 1});
  return x >= 0 && x <= s.width && y >= 0 && y <= s.height;
}

Footprint lonlat_box(const RasterSource& s) {
  const auto& gt = s.geotransform;
  const double x0 = gt[0], x1 = gt[0] + s.width * gt[1];
  const double y0 = gt[3], y1 = gt[3] + s.height * gt[5];
  Footprint f;
  f.south = std::max(-90.0, std::min(y0, y1));
  f.north = std::min(90.0, std::max(y0, y1));
  const double span = std::abs(x1 - x0);
  if (span >= 360.0 - 1e-9) {
    f.west = -180;
    f.east = 180;
  } else {
    f.west = std::remainder(std::min(x0, x1), 360.0);
    f.east = f.west + span;
  }
  f.polygons.push_back({{{f.west, f.south},
                         {f.east, f.south},
                         {f.east, f.north},
                         {f.west, f.north},
                         {f.west, f.south}}});
  if (f.east > 180) f.east -= 360;
  return f;
}

}  // namespace

std::string Footprint::describe() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "lon %.6g..%.6g, lat %.6g..%.6g", west, east, south, north);
  return buf;
}

Footprint source_footprint(const RasterSource& s) {
  const auto& gt = s.geotransform;
  if (s.geographic && gt[2] == 0 && gt[4] == 0) return lonlat_box(s);

  // The raster's outline in pixel coordinates, counter-clockwise on the page.
  std::vector<double> x, y;
  const auto edge = [&](double ax, double ay, double bx, double by) {
    for (int i = 0; i < kEdgePoints; ++i) {
      const double t = double(i) / kEdgePoints;
      x.push_back(ax + (bx - ax) * t);
      y.push_back(ay + (by - ay) * t);
    }
  };
  const double W = s.width, H = s.height;
  edge(0, 0, 0, H);
  edge(0, H, W, H);
  edge(W, H, W, 0);
  edge(W, 0, 0, 0);
  const SourceTransform t(s);
  t.to_lonlat(x, y);

  std::vector<LonLat> ring;
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::isnan(x[i])) continue;
    double lon = x[i];
    if (!ring.empty()) lon = ring.back().lon + std::remainder(lon - ring.back().lon, 360.0);
    ring.push_back({lon, y[i]});
  }
  if (ring.size() < 3) throw Error(s.path + ": no point of its outline transforms to lon/lat");
  // The longitude gained around the closed ring: +-360 when it winds around a pole.
  const double wind = ring.back().lon - ring.front().lon +
                      std::remainder(ring.front().lon - ring.back().lon, 360.0);
  Footprint f;
  if (std::abs(wind) > 180) {
    const double pole = inside(t, s, {0, 90}) ? 90 : -90;
    const double end = ring.back().lon, start = ring.front().lon;
    ring.push_back({end, pole});
    ring.push_back({start, pole});
    f.west = -180;
    f.east = 180;
  } else {
    const auto [lo, hi] = std::minmax_element(ring.begin(), ring.end(),
                                              [](LonLat a, LonLat b) { return a.lon < b.lon; });
    f.west = std::remainder(lo->lon, 360.0);
    f.east = std::remainder(hi->lon, 360.0);
  }
  ring.push_back(ring.front());
  f.south = 90;
  f.north = -90;
  for (const LonLat& p : ring) {
    f.south = std::min(f.south, p.lat);
    f.north = std::max(f.north, p.lat);
  }
  f.polygons.push_back({ring});
  return f;
}

namespace {

std::unique_ptr<OGRGeometry> ogr_polygons(const std::vector<PolygonRings>& polygons, double shift) {
  auto multi = std::make_unique<OGRMultiPolygon>();
  for (const PolygonRings& rings : polygons) {
    OGRPolygon polygon;
    for (const std::vector<LonLat>& ring : rings) {
      OGRLinearRing r;
      for (const LonLat& p : ring) r.addPoint(p.lon + shift, p.lat);
      r.closeRings();
      polygon.addRing(&r);
    }
    multi->addGeometry(&polygon);
  }
  return multi;
}

void add_polygons(const OGRGeometry& g, std::vector<PolygonRings>& out) {
  const OGRwkbGeometryType type = wkbFlatten(g.getGeometryType());
  if (type == wkbPolygon) {
    PolygonRings rings;
    for (const OGRLinearRing* r : *g.toPolygon()) {
      std::vector<LonLat>& ring = rings.emplace_back();
      for (const OGRPoint& p : *r) ring.push_back({p.getX(), p.getY()});
    }
    out.push_back(std::move(rings));
  } else if (type == wkbMultiPolygon || type == wkbGeometryCollection) {
    for (const OGRGeometry* part : *g.toGeometryCollection()) add_polygons(*part, out);
  }
}

}  // namespace

Footprint clipped_footprint(const Footprint& footprint, const std::vector<PolygonRings>& region) {
  const std::unique_ptr<OGRGeometry> source = ogr_polygons(footprint.polygons, 0);
  Footprint out;
  out.west = out.south = std::numeric_limits<double>::infinity();
  out.east = out.north = -std::numeric_limits<double>::infinity();
  for (const double shift : {-360.0, 0.0, 360.0}) {
    const std::unique_ptr<OGRGeometry> part(
        source->Intersection(ogr_polygons(region, shift).get()));
    if (!part || part->IsEmpty()) continue;
    add_polygons(*part, out.polygons);
    OGREnvelope e;
    part->getEnvelope(&e);
    out.west = std::min(out.west, e.MinX), out.east = std::max(out.east, e.MaxX);
    out.south = std::min(out.south, e.MinY), out.north = std::max(out.north, e.MaxY);
  }
  return out;
}

std::vector<CellId> cover_footprint(const Grid& grid, const Footprint& footprint, int level) {
  return cover_geojson(grid, footprint.polygons, level, Containment::Overlap);
}

double ground_pixel_m(const RasterSource& s) {
  const double cx = s.width / 2.0, cy = s.height / 2.0;
  std::vector<double> x{cx, cx + 1, cx}, y{cy, cy, cy + 1};
  SourceTransform(s).to_lonlat(x, y);
  if (std::isnan(x[0]) || std::isnan(x[1]) || std::isnan(x[2]))
    throw Error(s.path + ": its centre pixel does not transform to lon/lat");
  // Earth-centred coordinates: no singularity at the poles (a pixel may sit on one).
  std::array<std::array<double, 3>, 3> p;
  for (int i = 0; i < 3; ++i) {
    constexpr double kDeg = std::numbers::pi / 180;
    const double phi = y[size_t(i)] * kDeg, lam = x[size_t(i)] * kDeg;
    const double n = kA / std::sqrt(1 - kE2 * std::sin(phi) * std::sin(phi));
    p[size_t(i)] = {n * std::cos(phi) * std::cos(lam), n * std::cos(phi) * std::sin(lam),
                    n * (1 - kE2) * std::sin(phi)};
  }
  const auto d = [&](int i) {
    return std::array<double, 3>{p[size_t(i)][0] - p[0][0], p[size_t(i)][1] - p[0][1],
                                 p[size_t(i)][2] - p[0][2]};
  };
  const auto e = d(1), f = d(2);
  const double cx3 = e[1] * f[2] - e[2] * f[1], cy3 = e[2] * f[0] - e[0] * f[2],
               cz3 = e[0] * f[1] - e[1] * f[0];
  return std::sqrt(std::sqrt(cx3 * cx3 + cy3 * cy3 + cz3 * cz3));
}

}  // namespace maquette
