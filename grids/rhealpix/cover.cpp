#include "cover.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace maquette {
namespace {

// Distance from 0 to the interval [a, b].
double distance_to_zero(double a, double b) { return a > 0 ? a : b < 0 ? -b : 0; }

LonLatRect polar_rect(const RHealpixProjection& projection, int face, double u0, double v0,
                      double side) {
  const double x0 = u0 - 0.5, x1 = x0 + side, y0 = v0 - 0.5, y1 = y0 + side;
  // Latitude depends on the Chebyshev distance from the face centre (the pole) only.
  const double near = std::max(distance_to_zero(x0, x1), distance_to_zero(y0, y1));
  const double far = std::max({-x0, x1, -y0, y1});
  const double lat_near = projection.polar_latitude(face, near);
  const double lat_far = projection.polar_latitude(face, far);
  const double south = std::min(lat_near, lat_far), north = std::max(lat_near, lat_far);
  if (x0 < 0 && x1 > 0 && y0 < 0 && y1 > 0) return {-180, south, 180, north};
  // Longitude is constant along rays from the pole, so its extremes are at corners; they span
  // at most 180 degrees, measured from the centre's longitude.
  const double centre = projection.from_face({face, u0 + side / 2, v0 + side / 2}).lon;
  double lo = 0, hi = 0;
  for (const double u : {u0, u0 + side}) {
    for (const double v : {v0, v0 + side}) {
      if (u == 0.5 && v == 0.5) continue;  // the pole has every longitude
      const double d = std::remainder(projection.from_face({face, u, v}).lon - centre, 360.0);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  const double west = std::remainder(centre + lo, 360.0);
  const double wrapped = west == 180 ? -180 : west;
  return {wrapped, south, wrapped + (hi - lo), north};
}

class Coverer {
 public:
  Coverer(const RHealpixProjection& projection, const LonLatPolygon& region, int level,
          Containment mode)
      : projection_(projection), region_(region), level_(level), mode_(mode) {}

  std::vector<CellId> run() {
    std::vector<uint32_t> edges(region_.num_edges());
    std::iota(edges.begin(), edges.end(), 0U);
    for (int face = 0; face < CellId::kNumFaces; ++face) refine(CellId::FromFace(face), edges);
    return std::move(out_);
  }

 private:
  void refine(CellId cell, const std::vector<uint32_t>& candidates) {
    std::vector<uint32_t> crossing;
    const Relation relation = region_.relate(cell_rect(projection_, cell), candidates, crossing);
    if (relation == Relation::Inside) {
      const CellId end = cell.range_max().parent(level_).next();
      for (CellId c = cell.range_min().parent(level_); c != end; c = c.next()) out_.push_back(c);
    } else if (relation == Relation::Crosses && cell.level() < level_) {
      for (int d = 0; d < 4; ++d) refine(cell.child(d), crossing);
    } else if (relation == Relation::Crosses &&
               (mode_ == Containment::Overlap ||
                (mode_ == Containment::Centre &&
                 region_.contains(projection_.from_face(cell_point(cell, 0.5, 0.5)))))) {
      out_.push_back(cell);
    }
  }

  const RHealpixProjection& projection_;
  const LonLatPolygon& region_;
  const int level_;
  const Containment mode_;
  std::vector<CellId> out_;
};

}  // namespace

LonLatRect cell_rect(const RHealpixProjection& projection, CellId cell) {
  const double side = 1.0 / double(uint64_t(1) << cell.level());
  const auto [face, u0, v0] = cell_point(cell, 0, 0);
  if (face == kFaceN || face == kFaceS) return polar_rect(projection, face, u0, v0, side);
  const double west = -180 + (face - kFaceO + u0) * 90;
  return {west, projection.from_face({face, u0, v0 + side}).lat, west + side * 90,
          projection.from_face({face, u0, v0}).lat};
}

std::vector<CellId> cover(const RHealpixProjection& projection, const LonLatPolygon& region,
                          int level, Containment mode) {
  return Coverer(projection, region, level, mode).run();
}

}  // namespace maquette
