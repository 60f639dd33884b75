// The oracle of content standing on a DEM of EGM96 heights (SRTM's datum, the ingest's default):
// heights above EGM96 (EPSG:4326+5773) to heights above the WGS 84 ellipsoid (EPSG:4979), by PROJ
// through GDAL, independently of the program's gdal/vertical_datum.h.
#pragma once

#include <memory>

class OGRCoordinateTransformation;

namespace maquette::test {

class Egm96ToEllipsoid {
 public:
  Egm96ToEllipsoid();  // fails the test (gtest) when PROJ has no such transformation
  ~Egm96ToEllipsoid();
  // The ellipsoidal height of `height` above EGM96 at (lon, lat) degrees; NaN (and a test
  // failure) where PROJ cannot transform it.
  double operator()(double lon, double lat, double height) const;

 private:
  std::unique_ptr<OGRCoordinateTransformation> transform_;
};

}  // namespace maquette::test
