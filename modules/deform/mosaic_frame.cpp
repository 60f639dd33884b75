#include "mosaic_frame.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace maquette::deform {
namespace {

// Mean Earth radius (m): the depth of the tangent plane below which a point at horizontal
// distance d lies on the ellipsoid is about d^2 / 2R.
constexpr double kEarthRadiusM = 6371008.8;

}  // namespace

MosaicFrame::MosaicFrame(const Grid& grid, int face, int pixel_level, int64_t origin_col,
                         int64_t origin_row, LonLat reference)
    : samples_(grid, face, pixel_level, origin_col, origin_row),
      origin_{double(origin_col), double(origin_row)},
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

std::optional<LonLat> MosaicFrame::sample_centre(int col, int row) const {
  return samples_.sample_lonlat(col, row);
}

LonLat MosaicFrame::sample_lonlat(int col, int row) const {
  const auto centre = sample_centre(col, row);
  if (!centre)
    throw Error("mosaic sample (" + std::to_string(col) + ", " + std::to_string(row) +
                ") lies in no face of the plane unfolded around face " +
                CellId::FromFace(samples_.face()).ToText());
  return *centre;
}

std::optional<std::array<double, 2>> MosaicFrame::sample(LonLat p) const {
  return samples_.sample(p);
}

std::array<double, 2> MosaicFrame::local_sample(EastNorth2 p) const {
  const auto s = sample(lonlat(p));
  return s ? *s : std::array<double, 2>{NAN, NAN};
}

}  // namespace maquette::deform
