// Where the samples of a DEM tile lie in a camera's east-north-up frame, without three exact
// transforms per sample (the rHEALPix inverse projection, the vertical datum's shift through PROJ
// and GeographicLib's ENU): a sample at height z of the datum lies at base + z up, where base is
// the ENU point at height 0 of the datum and up the ellipsoid's unit normal there (exact: geodetic
// heights run along the normal). The tile's inside takes lon/lat, base and up bilinearly from a
// lattice of exact places 1/32 of the tile apart (every 8 samples of a 256-sample tile); the
// halo's rings, which may lie on another face turned (core/halo.h), are placed exactly, as is every
// sample of a tile whose lattice spans more than 90 degrees of longitude (the antimeridian),
// reaches beyond 80 degrees of latitude (longitudes bend fast near a pole) or turns by more than
// a hundredth of a radian at a node (a polar face's diagonal crosses it: the meridians 0, 90, 180
// and -90 poleward of 42 degrees, where rows of samples bend by tens of degrees on the ground). The
// error against PROJ is tested (tests/render sample_places_test: within a thousandth of a sample; 4
// mm for 35 m samples). Only the lattice and the halo's places are kept (a quarter of a megabyte
// for a 256-sample tile with two rings); an inside sample's place is interpolated, or without a
// lattice placed exactly, when asked for, the same bits each time.
#pragma once

#include <cmath>
#include <utility>
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
  // samples. Precondition: 0 <= halo <= size. `grid` and `heights` are used by `at` without a
  // lattice: they must outlive the object.
  SamplePlaces(const Grid& grid, CellId cell, int size, int halo, const EnuFrame& frame,
               const EllipsoidalHeights& heights);
  // Precondition: -halo <= col, row < size + halo.
  SamplePlace at(int col, int row) const;
  // The same place's base and up alone (the same bits as at's; its position and plane left
  // unset): what drawing a sample needs, without interpolating the rest.
  SamplePlace ground(int col, int row) const;
  // Whether the inside samples' places are interpolated from the lattice, whose rows and columns
  // then turn by at most a hundredth of a radian at a node (else every place is exact).
  bool interpolated() const { return lattice_ > 0; }

 private:
  size_t border_slot(int col, int row) const;
  SamplePlace exact_place(int col, int row) const;  // unknown beyond one face width
  PlanePoint plane(int col, int row) const;         // the sample's centre on the cell's face
  // An inside sample's four lattice nodes and their bilinear weights (a lattice required).
  struct Corners {
    const SamplePlace* node[4];
    double weight[4];
  };
  Corners corners(int col, int row) const;
  // Sets s.base and s.up from `c` (zero before).
  static void add_ground(const Corners& c, SamplePlace& s);

  int size_, halo_;
  const Grid* grid_;
  CellId cell_;
  EnuFrame frame_;
  const EllipsoidalHeights* heights_;
  int pixel_level_;                  // the samples' level
  FaceCoord origin_;                 // sample (0, 0) on the cell's face
  int lattice_ = 0;                  // intervals per side; 0: every place exact (exact_place)
  PlaneSquare square_{};             // the cell's square in the grid's plane
  std::vector<SamplePlace> border_;  // the halo's rings: rows above, rows below, then the sides
  std::vector<SamplePlace> nodes_;   // (lattice + 1)^2, row-major
  // With a lattice, per sample 0 .. size - 1 (a row or a column: the same), the lattice interval
  // holding it and its fraction along it: corners' two divisions a sample made once a tile.
  std::vector<std::pair<int, double>> steps_;
};

}  // namespace maquette
