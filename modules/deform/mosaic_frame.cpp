#include "mosaic_frame.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/halo.h"

namespace maquette::deform {
namespace {

// Mean Earth radius (m): the depth of the tangent plane below which a point at horizontal
// distance d lies on the ellipsoid is about d^2 / 2R.
constexpr double kEarthRadiusM = 6371008.8;

}  // namespace

MosaicFrame::MosaicFrame(const Grid& grid, int face, int pixel_level, int64_t origin_col,
                         int64_t origin_row, LonLat reference)
    : grid_(grid),
      plane_(grid, face, pixel_level),
      origin_col_(origin_col),
      origin_row_(origin_row),
      tangent_plane_({reference.lon, reference.lat, 0}) {}

EastNorth2 MosaicFrame::local(LonLat p) const {
  const auto [x, y, z] = tangent_plane_.to_enu(p.lon, p.lat);
  return {x, y};
}

LonLat MosaicFrame::lonlat(EastNorth2 p) const {
  const double depth = (p[0] * p[0] + p[1] * p[1]) / (2 * kEarthRadiusM);
  const GeodeticPoint g = tangent_plane_.to_geodetic(p[0], p[1], -depth);
  return {g.lon, g.lat};
}

LonLat MosaicFrame::sample_lonlat(int col, int row) const {
  const auto pixel = plane_.from_anchor(origin_col_ + col, origin_row_ + row);
  if (!pixel)
    throw Error("mosaic sample (" + std::to_string(col) + ", " + std::to_string(row) +
                ") lies in no face of the plane unfolded around face " +
                CellId::FromFace(plane_.anchor()).ToText());
  return pixel_centre(grid_, *pixel, plane_.level());
}

std::optional<std::array<double, 2>> MosaicFrame::sample(LonLat p) const {
  const int face = grid_.cell_from_point(p, 0).face();
  const PlaneSquare square = grid_.plane_square(CellId::FromFace(face));
  const PlanePoint q = grid_.forward(p);
  const double pixels = std::ldexp(1.0, plane_.level());
  const auto at = plane_.to_anchor(face, (q.x - square.x_min) / square.side * pixels - 0.5,
                                   (square.y_max - q.y) / square.side * pixels - 0.5);
  if (!at) return std::nullopt;
  return std::array<double, 2>{(*at)[0] - double(origin_col_), (*at)[1] - double(origin_row_)};
}

}  // namespace maquette::deform
