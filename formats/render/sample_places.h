// Where the samples of a DEM tile lie in a camera's east-north-up frame, without three exact
// transforms per sample (the rHEALPix inverse projection, the vertical datum's shift through PROJ
// and GeographicLib's ENU): a sample at height z of the datum lies at base + z up, where base is
// the ENU point at height 0 of the datum and up the ellipsoid's unit normal there (exact: geodetic
// heights run along the normal). The tile's inside takes lon/lat, base and up bilinearly from a
// lattice of exact places 1/32 of the tile apart (every 8 samples of a 256-sample tile); the
// halo's rings, which may lie on another face turned (core/halo.h), are placed exactly, as is every
// sample of a tile whose lattice spans more than 90 degrees of longitude (the antimeridian) or
// reaches beyond 80 degrees of latitude (longitudes bend fast near a pole). The error against PROJ
// is tested (tests/render sample_places_test: within a thousandth of a sample; 4 mm for 35 m
// samples).
#pragma once

#include <cmath>
#include <vector>

#include "core/enu_frame.h"
#include "core/grid.h"
#include "gdal/vertical_datum.h"
#include "render/camera.h"

namespace maquette {

struct SamplePlace {
  LonLat position;     // degrees
  Vec3d base{};        // the point at height 0 of the DEM's datum, ENU metres
  Vec3d up{};          // the ellipsoid's unit normal there, in the ENU frame
  bool known = false;  // false beyond one face width (core/halo.h pixel_source)
  // The sample's centre in the grid's plane (Grid::forward) when it lies on the cell's own face
  // where the face's regular lattice puts it (exactly: pixel squares); NaN for a halo sample
  // read from another face, whose plane is turned or elsewhere.
  PlanePoint plane{NAN, NAN};
};

class SamplePlaces {
 public:
  // Samples -halo .. size + halo - 1 (the halo's rings included) of `cell`'s tile of `size`
  // samples. Precondition: 0 <= halo <= size.
  SamplePlaces(const Grid& grid, CellId cell, int size, int halo, const EnuFrame& frame,
               const EllipsoidalHeights& heights);
  const SamplePlace& at(int col, int row) const {
    return places_[size_t(row + halo_) * size_t(size_ + 2 * halo_) + size_t(col + halo_)];
  }

 private:
  int size_, halo_;
  std::vector<SamplePlace> places_;  // (size + 2 halo)^2, row-major from (-halo, -halo)
};

}  // namespace maquette
