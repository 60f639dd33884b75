#include "roof_triangulation.h"

#include <geos_c.h>

#include <algorithm>
#include <memory>
#include <tuple>

namespace maquette::structures {
namespace {

// A GEOS context per thread (the reentrant API), finished with the thread.
GEOSContextHandle_t geos() {
  struct Context {
    GEOSContextHandle_t h = GEOS_init_r();
    ~Context() { GEOS_finish_r(h); }
  };
  thread_local Context context;
  return context.h;
}

struct GeometryDeleter {
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(geos(), g); }
};
using GeometryPtr = std::unique_ptr<GEOSGeometry, GeometryDeleter>;

GEOSGeometry* linear_ring(const PlaneRing& ring) {
  std::vector<double> xy;
  xy.reserve(2 * ring.size() + 2);
  for (const PlanePoint2& p : ring) xy.insert(xy.end(), {p[0], p[1]});
  xy.insert(xy.end(), {ring[0][0], ring[0][1]});
  GEOSCoordSequence* seq = GEOSCoordSeq_copyFromBuffer_r(geos(), xy.data(), ring.size() + 1, 0, 0);
  return GEOSGeom_createLinearRing_r(geos(), seq);
}

GeometryPtr polygon(const Footprint& footprint) {
  std::vector<GEOSGeometry*> holes;
  for (size_t k = 1; k < footprint.rings.size(); ++k)
    holes.push_back(linear_ring(footprint.rings[k]));
  return GeometryPtr(GEOSGeom_createPolygon_r(geos(), linear_ring(footprint.rings[0]), holes.data(),
                                              unsigned(holes.size())));
}

}  // namespace

std::vector<uint32_t> triangulate_footprint(const Footprint& footprint) {
  // GEOS returns triangles of the input's own coordinates: find each one's index.
  std::vector<std::tuple<double, double, uint32_t>> points;
  for (const PlaneRing& ring : footprint.rings)
    for (const PlanePoint2& p : ring) points.emplace_back(p[0], p[1], uint32_t(points.size()));
  std::sort(points.begin(), points.end());
  const auto index_of = [&](double x, double y) {
    const auto it = std::lower_bound(points.begin(), points.end(), std::make_tuple(x, y, 0u));
    if (it == points.end() || std::get<0>(*it) != x || std::get<1>(*it) != y)
      throw InvalidFootprint(
          "GEOS triangulated its roof with a corner that is not a footprint point");
    return std::get<2>(*it);
  };

  const GeometryPtr triangles(
      GEOSConstrainedDelaunayTriangulation_r(geos(), polygon(footprint).get()));
  if (!triangles) throw InvalidFootprint("GEOS could not triangulate its roof");
  std::vector<uint32_t> indices;
  const int n = GEOSGetNumGeometries_r(geos(), triangles.get());
  indices.reserve(3 * size_t(n));
  for (int t = 0; t < n; ++t) {
    const GEOSGeometry* ring =
        GEOSGetExteriorRing_r(geos(), GEOSGetGeometryN_r(geos(), triangles.get(), t));
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(geos(), ring);
    std::array<double, 6> xy{};
    for (unsigned k = 0; k < 3; ++k)
      GEOSCoordSeq_getXY_r(geos(), seq, k, &xy[2 * k], &xy[2 * k + 1]);
    const double twice = (xy[2] - xy[0]) * (xy[5] - xy[1]) - (xy[3] - xy[1]) * (xy[4] - xy[0]);
    const uint32_t a = index_of(xy[0], xy[1]), b = index_of(xy[2], xy[3]),
                   c = index_of(xy[4], xy[5]);
    if (twice >= 0)
      indices.insert(indices.end(), {a, b, c});
    else
      indices.insert(indices.end(), {a, c, b});
  }
  return indices;
}

}  // namespace maquette::structures
