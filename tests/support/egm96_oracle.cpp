#include "egm96_oracle.h"

#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>

namespace maquette::test {

Egm96ToEllipsoid::Egm96ToEllipsoid() {
  OGRSpatialReference egm96, ellipsoidal;
  EXPECT_EQ(egm96.SetFromUserInput("EPSG:4326+5773"), OGRERR_NONE);
  EXPECT_EQ(ellipsoidal.SetFromUserInput("EPSG:4979"), OGRERR_NONE);
  egm96.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  ellipsoidal.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  transform_.reset(OGRCreateCoordinateTransformation(&egm96, &ellipsoidal));
  EXPECT_TRUE(transform_) << "no EGM96 to WGS 84 transformation";
}

Egm96ToEllipsoid::~Egm96ToEllipsoid() = default;

double Egm96ToEllipsoid::operator()(double lon, double lat, double height) const {
  double x = lon, y = lat, z = height;
  const bool done = transform_ && transform_->Transform(1, &x, &y, &z);
  EXPECT_TRUE(done) << "EGM96 height at (" << lon << ", " << lat << ")";
  return done ? z : std::nan("");
}

}  // namespace maquette::test
