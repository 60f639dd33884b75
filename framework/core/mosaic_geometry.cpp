#include "core/mosaic_geometry.h"

#include <cmath>

#include "core/halo.h"

namespace maquette {

MosaicGeometry::MosaicGeometry(const Grid& grid, int face, int pixel_level, int64_t origin_col,
                               int64_t origin_row)
    : grid_(grid),
      plane_(grid, face, pixel_level),
      origin_col_(origin_col),
      origin_row_(origin_row) {}

std::optional<LonLat> MosaicGeometry::sample_lonlat(int64_t col, int64_t row) const {
  const auto pixel = plane_.from_anchor(origin_col_ + col, origin_row_ + row);
  if (!pixel) return std::nullopt;
  return pixel_centre(grid_, *pixel, plane_.level());
}

std::optional<std::array<double, 2>> MosaicGeometry::sample(LonLat p) const {
  const int face = grid_.cell_from_point(p, 0).face();
  const PlaneSquare square = grid_.plane_square(CellId::FromFace(face));
  const PlanePoint q = grid_.forward(p);
  const double pixels = std::ldexp(1.0, plane_.level());
  // - 0.5: the inverse of pixel_centre's + 0.5.
  const auto at = plane_.to_anchor(face, (q.x - square.x_min) / square.side * pixels - 0.5,
                                   (square.y_max - q.y) / square.side * pixels - 0.5);
  if (!at) return std::nullopt;
  return std::array<double, 2>{(*at)[0] - double(origin_col_), (*at)[1] - double(origin_row_)};
}

}  // namespace maquette
