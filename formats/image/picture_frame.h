// The frame of a 2D picture of the globe: its projection and pixel grid. Plate carrée (lon/lat)
// suits most regions and the whole globe; a polar cap in lon/lat degenerates into a long thin
// strip, so regions around one pole are drawn in a Lambert azimuthal equal-area projection
// centred on that pole (WGS84, metres, longitude 0 down from the north pole, up from the south).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/grid.h"

class OGRCoordinateTransformation;

namespace maquette {

enum class Projection { Auto, LonLat, NorthPolar, SouthPolar };
// "auto", "lonlat" or "polar" (the pole the region is around); throws maquette::Error.
Projection parse_projection(std::string_view name);

struct PictureFrame {
  Projection projection = Projection::LonLat;  // never Auto
  double left = 0, top = 0;                    // top-left corner: degrees or metres
  double x_step = 0, y_step = 0;               // pixel width and height (> 0)
  int width = 0, height = 0;

  // GDAL's geotransform and the CRS as WKT (EPSG:4326 in lon/lat order for LonLat).
  std::array<double, 6> geotransform() const;
  std::string crs_wkt() const;
  std::string crs_name() const;  // "lon/lat", "north polar LAEA", "south polar LAEA"
};

// What a picture shows: a lon/lat box (west > east crosses the antimeridian), or the outline
// of cells and the poles they hold.
struct PictureRegion {
  std::optional<std::array<double, 4>> bbox;  // west south east north, degrees
  std::vector<CellId> cells;                  // the region's cells when there is no bbox
};

// The frame covering `region` with pixels of about `pixel_m` metres, or larger so that its
// longer side fits `max_side` (`doublings`: log2 of the ratio, rounded down). Auto picks a
// polar frame for a region around exactly one pole (or poleward of 60 degrees and wider than 90
// degrees of longitude), else lon/lat. A box gives a frame that covers exactly the box.
PictureFrame frame_for(const Grid& grid, const PictureRegion& region, Projection projection,
                       double pixel_m, int max_side, int& doublings);

// Lon/lat of the centres of a frame's pixels, a row at a time. Not for use by several threads.
class FramePixels {
 public:
  explicit FramePixels(const PictureFrame& frame);
  void row(int row, std::vector<LonLat>& out) const;  // width points

 private:
  PictureFrame frame_;
  std::shared_ptr<OGRCoordinateTransformation> to_lonlat_;  // polar frames
};

// An n x n lattice of points over a lon/lat box, its edges included (n >= 2; longitudes east of
// the antimeridian may exceed 180).
std::vector<LonLat> bbox_points(const std::array<double, 4>& bbox, int n);

// Whether a point lies in a lon/lat box (west > east crosses the antimeridian).
bool in_bbox(const std::array<double, 4>& bbox, LonLat p);

}  // namespace maquette
