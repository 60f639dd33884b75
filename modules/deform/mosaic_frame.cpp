#include "mosaic_frame.h"

#include <cmath>

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
      face_(face),
      pixel_level_(pixel_level),
      origin_col_(origin_col),
      origin_row_(origin_row),
      face_square_(grid.plane_square(CellId::FromFace(face))),
      tangent_plane_(reference.lat, reference.lon, 0) {}

EastNorth2 MosaicFrame::local(LonLat p) const {
  double x = 0, y = 0, z = 0;
  tangent_plane_.Forward(p.lat, p.lon, 0, x, y, z);
  return {x, y};
}

LonLat MosaicFrame::lonlat(EastNorth2 p) const {
  double lat = 0, lon = 0, h = 0;
  const double depth = (p[0] * p[0] + p[1] * p[1]) / (2 * kEarthRadiusM);
  tangent_plane_.Reverse(p[0], p[1], -depth, lat, lon, h);
  return {lon, lat};
}

LonLat MosaicFrame::sample_lonlat(int col, int row) const {
  return pixel_centre(grid_, {face_, origin_col_ + col, origin_row_ + row}, pixel_level_);
}

std::optional<std::array<double, 2>> MosaicFrame::sample(LonLat p) const {
  if (grid_.cell_from_point(p, 0).face() != face_) return std::nullopt;
  const PlanePoint q = grid_.forward(p);
  const double pixels = std::ldexp(1.0, pixel_level_);
  const double col = (q.x - face_square_.x_min) / face_square_.side * pixels - 0.5;
  const double row = (face_square_.y_max - q.y) / face_square_.side * pixels - 0.5;
  return std::array<double, 2>{col - double(origin_col_), row - double(origin_row_)};
}

}  // namespace maquette::deform
