#include "cover.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "core/region.h"

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

// Whether the cell is a lon/lat rectangle, so that its bounding rectangle is exact: cells of the
// equatorial faces, the polar faces themselves, and the four cells at each pole (a pole corner
// x = y = 0: their edges are meridians, on the axes, and parallels, at Chebyshev distance side).
bool is_lonlat_rectangle(CellId cell) {
  if (cell.face() != kFaceN && cell.face() != kFaceS) return true;
  const uint32_t half = uint32_t(1) << cell.level() >> 1;
  const auto at_pole = [half](uint32_t i) { return i == half || i + 1 == half; };
  return cell.level() == 0 || (at_pole(cell.col()) && at_pole(cell.row()));
}

// The boundary of a polar cell that does not touch a pole as a closed lon/lat ring (continuous
// longitudes, the westmost in [-180, 180)), inset by kInset cell widths and densified.
//
// Each cell edge lies in one quarter of the face (the diagonals meet it only at corners). An
// edge across the rays from the pole is a parallel, straight in lon/lat; one along them, at
// offset dx from the quarter's axis and Chebyshev distance r from the pole, is the curve
// lon = lon_c + 45 dx / r, lat = polar_latitude(r), which m chords replace. Mapped back to the
// face, a chord strays from its edge by at most 0.28 side^2 / (m^2 r_min) face widths, r_min
// the cell's Chebyshev distance from the pole (measured over every polar cell of levels 2-6 and
// sampled ones of levels 8 and 12, m = 1..16; the worst cells are next to the pole cells,
// r_min = side), so m = ceil(sqrt(300 side / r_min)) chords per edge (at most 18) keep the ring
// within 1e-3 side of the inset cell (checked to level 20).
//
// The inset (1e-5 side, far above rounding even at level 29) turns the exact contacts common
// on polar faces (a region edge along a parallel or meridian holding cell edges, a box reaching
// the pole) into clear cases: a cell touching the region from outside is no Overlap, one
// touching its boundary from inside is Full. So Overlap and Full are exact except for cells
// whose boundary comes within ~1e-3 of their width of the region's boundary.
constexpr double kInset = 1e-5;

std::vector<LonLat> inset_ring(const RHealpixProjection& projection, CellId cell) {
  const double side = 1.0 / double(uint64_t(1) << cell.level());
  const auto [face, u0, v0] = cell_point(cell, 0, 0);
  const double x0 = u0 - 0.5, y0 = v0 - 0.5;
  const double r_min = std::max(distance_to_zero(x0, x0 + side), distance_to_zero(y0, y0 + side));
  const int m = int(std::ceil(std::sqrt(300 * side / std::max(r_min, side))));
  // Counter-clockwise in the plane: down the left edge, right along the bottom, up the right
  // edge, left along the top.
  const double a = kInset, b = 1 - kInset;
  std::vector<LonLat> ring;
  ring.reserve(size_t(4 * m + 1));
  for (int edge = 0; edge < 4; ++edge) {
    for (int i = 0; i < m; ++i) {
      const double t = a + (b - a) * i / m, rt = a + b - t;
      const double fu[4] = {a, t, b, rt}, fv[4] = {t, b, rt, a};
      LonLat p = projection.from_face(cell_point(cell, fu[edge], fv[edge]));
      if (!ring.empty()) p.lon += 360 * std::round((ring.back().lon - p.lon) / 360);
      ring.push_back(p);
    }
  }
  ring.push_back(ring.front());
  double west = ring.front().lon;
  for (const LonLat& p : ring) west = std::min(west, p.lon);
  const double shift = -360 * std::floor((west + 180) / 360);
  for (LonLat& p : ring) p.lon += shift;
  return ring;
}

class Coverer {
 public:
  Coverer(const RHealpixProjection& projection, std::span<const LonLatPolygon> regions, int level,
          Containment mode, const std::function<void(CellId)>& visit)
      : projection_(projection), regions_(regions), level_(level), mode_(mode), visit_(visit) {}

  void run() {
    Candidates all(regions_.size());
    for (size_t i = 0; i < regions_.size(); ++i) {
      all[i].emplace(regions_[i].num_edges());
      std::iota(all[i]->begin(), all[i]->end(), 0U);
    }
    for (int face = 0; face < CellId::kNumFaces; ++face) refine(CellId::FromFace(face), all);
  }

 private:
  // Per region, the edges that may cross a cell; empty optional: the region is disjoint from it.
  using Candidates = std::vector<std::optional<std::vector<uint32_t>>>;

  void refine(CellId cell, const Candidates& candidates) {
    const LonLatRect rect = cell_rect(projection_, cell);
    Candidates crossing(regions_.size());
    bool crosses = false;
    for (size_t i = 0; i < regions_.size(); ++i) {
      if (!candidates[i]) continue;
      std::vector<uint32_t> edges;
      const Relation relation = regions_[i].relate(rect, *candidates[i], edges);
      if (relation == Relation::Inside) return visit_(cell);
      if (relation == Relation::Crosses) {
        crossing[i] = std::move(edges);
        crosses = true;
      }
    }
    if (!crosses) return;
    if (cell.level() < level_) {
      for (int d = 0; d < 4; ++d) refine(cell.child(d), crossing);
      return;
    }
    for (size_t i = 0; i < regions_.size(); ++i)
      if (crossing[i] && in_boundary_cell(regions_[i], cell, *crossing[i])) return visit_(cell);
  }

  // A cell at the target level whose rectangle crosses the region's boundary (`crossing`: the
  // region edges meeting the rectangle). When the cell is its rectangle, an edge crosses its
  // interior: it overlaps the region and is not inside it. Other cells (polar) are tested by
  // their densified boundary.
  bool in_boundary_cell(const LonLatPolygon& region, CellId cell,
                        const std::vector<uint32_t>& crossing) const {
    switch (mode_) {
      case Containment::Centre:
        return region.contains(projection_.from_face(cell_point(cell, 0.5, 0.5)));
      case Containment::Overlap:
        return is_lonlat_rectangle(cell) ||
               region.relate_ring(inset_ring(projection_, cell), crossing) != Relation::Disjoint;
      case Containment::Full:
        return !is_lonlat_rectangle(cell) &&
               region.relate_ring(inset_ring(projection_, cell), crossing) == Relation::Inside;
    }
    return false;
  }

  const RHealpixProjection& projection_;
  const std::span<const LonLatPolygon> regions_;
  const int level_;
  const Containment mode_;
  const std::function<void(CellId)>& visit_;
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
  std::vector<CellId> out;
  visit_cover(projection, std::span(&region, 1), level, mode, [&out, level](CellId cell) {
    for_each_at_level(cell, level, [&out](CellId c) { out.push_back(c); });
  });
  return out;
}

void visit_cover(const RHealpixProjection& projection, std::span<const LonLatPolygon> regions,
                 int level, Containment mode, const std::function<void(CellId)>& visit) {
  Coverer(projection, regions, level, mode, visit).run();
}

}  // namespace maquette
