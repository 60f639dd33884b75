#include "rhealpix_grid.h"

#include <cmath>

#include "cover.h"
#include "faces.h"

namespace maquette {
namespace {

constexpr double kPi = RHealpixProjection::kPi;

// Unwraps `lon` to within 180 degrees of `previous`.
double unwrap(double lon, double previous) {
  return lon + 360 * std::round((previous - lon) / 360);
}

}  // namespace

void RHealpixGrid::check_cell(CellId cell) {
  if (!cell.is_valid()) throw Error("invalid cell id " + std::to_string(cell.id()));
}

PlanePoint RHealpixGrid::forward(LonLat p) const {
  return projection_.to_plane(projection_.to_face(p));
}

LonLat RHealpixGrid::inverse(PlanePoint p) const {
  return projection_.from_face(projection_.from_plane(p));
}

void RHealpixGrid::cells_from_points(std::span<const LonLat> points, int level,
                                     std::span<CellId> out) const {
  CellId::CheckLevel(level);
  if (out.size() != points.size()) {
    throw Error("cells_from_points: " + std::to_string(points.size()) + " points but room for " +
                std::to_string(out.size()) + " cells");
  }
  for (size_t i = 0; i < points.size(); ++i)
    out[i] = cell_at(projection_.to_face(points[i]), level);
}

LonLat RHealpixGrid::centre(CellId cell) const {
  check_cell(cell);
  return projection_.from_face(cell_point(cell, 0.5, 0.5));
}

PlaneSquare RHealpixGrid::plane_square(CellId cell) const {
  check_cell(cell);
  const FacePoint corner = cell_point(cell, 0, 0);
  const PlanePoint top_left = projection_.to_plane(corner);
  return {top_left.x, top_left.y, projection_.radius() * kPi / 2 / double(1 << cell.level())};
}

std::vector<LonLat> RHealpixGrid::boundary(CellId cell, int points_per_edge) const {
  check_cell(cell);
  if (points_per_edge < 1) {
    throw Error("invalid points_per_edge " + std::to_string(points_per_edge) + ": expected >= 1");
  }
  // Counter-clockwise in the plane (y up, v down), which the projection keeps on the ellipsoid:
  // down the left edge, right along the bottom, up the right edge, left along the top.
  const int m = points_per_edge;
  std::vector<FacePoint> samples;
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < m; ++i) {
      const double f = double(i) / m;
      const double fu[4] = {0, f, 1, 1 - f};
      const double fv[4] = {f, 1, 1 - f, 0};
      samples.push_back(cell_point(cell, fu[side], fv[side]));
    }
  }
  const auto is_pole = [](const FacePoint& p) {
    return (p.face == kFaceN || p.face == kFaceS) && p.u == 0.5 && p.v == 0.5;
  };
  // Start away from a pole, whose longitude is taken from its neighbours on the ring.
  if (is_pole(samples[0])) std::rotate(samples.begin(), samples.begin() + 1, samples.end());
  const double pole_lat = cell.face() == kFaceN ? 90 : -90;
  std::vector<LonLat> ring;
  bool after_pole = false;
  for (size_t i = 0; i <= samples.size(); ++i) {
    const FacePoint& s = samples[i % samples.size()];
    if (is_pole(s)) {
      ring.push_back({ring.back().lon, pole_lat});
      after_pole = true;
      continue;
    }
    LonLat p = projection_.from_face(s);
    if (!ring.empty()) p.lon = unwrap(p.lon, ring.back().lon);
    if (after_pole) ring.push_back({p.lon, pole_lat});
    after_pole = false;
    ring.push_back(p);
  }
  // Around a pole the longitudes grow by 360: close the ring along the pole.
  if (std::abs(ring.back().lon - ring.front().lon) > 180) {
    ring.push_back({ring.back().lon, pole_lat});
    ring.push_back({ring.front().lon, pole_lat});
    ring.push_back(ring.front());
  }
  return ring;
}

double RHealpixGrid::area(int level) const {
  CellId::CheckLevel(level);
  const double r = projection_.radius();
  return 4 * kPi * r * r / (6 * std::ldexp(1.0, 2 * level));
}

LevelInfo RHealpixGrid::level_info(int level, int tile_size) const {
  if (tile_size < 1) {
    throw Error("invalid tile size " + std::to_string(tile_size) + ": expected >= 1");
  }
  const double a = area(level);
  const double side = std::sqrt(a);
  return {level, side, projection_.radius() * kPi / 2 / std::ldexp(1.0, level), a,
          side / tile_size};
}

std::optional<FaceCoord> RHealpixGrid::wrap(FaceCoord c, int level) const {
  // Pixel coordinates use levels beyond the cell levels; 2^61 still fits the arithmetic.
  if (level < 0 || level > 60) {
    throw Error("invalid wrap level " + std::to_string(level) + ": expected 0..60");
  }
  if (c.face < 0 || c.face >= CellId::kNumFaces) {
    throw Error("invalid face " + std::to_string(c.face) + ": expected 0..5");
  }
  return wrap_face_coord(c, level);
}

std::array<CellId, 4> RHealpixGrid::edge_neighbours(CellId cell) const {
  check_cell(cell);
  const int level = cell.level();
  const int64_t col = cell.col(), row = cell.row();
  constexpr int kDc[4] = {0, 1, 0, -1}, kDr[4] = {-1, 0, 1, 0};  // top, right, bottom, left
  std::array<CellId, 4> out;
  for (int i = 0; i < 4; ++i) {
    const FaceCoord c = *wrap_face_coord({cell.face(), col + kDc[i], row + kDr[i]}, level);
    out[size_t(i)] = CellId::FromFaceColRow(c.face, level, uint32_t(c.col), uint32_t(c.row));
  }
  return out;
}

std::vector<CellId> RHealpixGrid::vertex_neighbours(CellId cell) const {
  check_cell(cell);
  const int level = cell.level();
  const int64_t n = int64_t(1) << level;
  const int64_t col = cell.col(), row = cell.row();
  std::vector<CellId> out;
  for (int64_t dr = -1; dr <= 1; ++dr) {
    for (int64_t dc = -1; dc <= 1; ++dc) {
      const int64_t c = col + dc, r = row + dr;
      // Skip the cell itself and the missing quadrant beyond a face (= cube) corner.
      if ((dc == 0 && dr == 0) || ((c < 0 || c >= n) && (r < 0 || r >= n))) continue;
      const FaceCoord w = *wrap_face_coord({cell.face(), c, r}, level);
      out.push_back(CellId::FromFaceColRow(w.face, level, uint32_t(w.col), uint32_t(w.row)));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

// A lon/lat box as a polygon's ring with continuous longitudes (east beyond 180 across the
// antimeridian, [-180, 540) for every longitude: wide enough to hold every cell's unwrapped
// range).
std::vector<LonLat> box_ring(double west, double south, double east, double north, int level) {
  CellId::CheckLevel(level);
  if (!(south >= -90 && north <= 90 && south <= north) || !std::isfinite(west) ||
      !std::isfinite(east)) {
    throw Error("invalid bbox west " + std::to_string(west) + ", south " + std::to_string(south) +
                ", east " + std::to_string(east) + ", north " + std::to_string(north) +
                ": expected finite longitudes and -90 <= south <= north <= 90");
  }
  if (east - west >= 360) {
    west = -180;
    east = 540;
  } else if (west > east) {
    east += 360;
  }
  return {{west, south}, {east, south}, {east, north}, {west, north}};
}

}  // namespace

std::vector<CellId> RHealpixGrid::cover_bbox(double west, double south, double east, double north,
                                             int level, Containment mode) const {
  return cover_polygon({box_ring(west, south, east, north, level)}, level, mode);
}

std::vector<CellId> RHealpixGrid::cover_polygon(const std::vector<std::vector<LonLat>>& rings,
                                                int level, Containment mode) const {
  CellId::CheckLevel(level);
  return cover(projection_, LonLatPolygon(rings), level, mode);
}

void RHealpixGrid::visit_cover_bbox(double west, double south, double east, double north, int level,
                                    Containment mode,
                                    const std::function<void(CellId)>& visit) const {
  const LonLatPolygon box({box_ring(west, south, east, north, level)});
  maquette::visit_cover(projection_, std::span(&box, 1), level, mode, visit);
}

void RHealpixGrid::visit_cover_polygons(
    const std::vector<std::vector<std::vector<LonLat>>>& polygons, int level, Containment mode,
    const std::function<void(CellId)>& visit) const {
  CellId::CheckLevel(level);
  std::vector<LonLatPolygon> regions;
  for (const auto& rings : polygons) regions.emplace_back(rings);
  maquette::visit_cover(projection_, regions, level, mode, visit);
}

const Grid& default_grid() {
  static const RHealpixGrid grid;
  return grid;
}

}  // namespace maquette
