// The cone of cone_dem.h seen from an eye: its surface in PROJ's east-north-up frame at the eye
// (cone points from UTM 12 through PROJ), and the two generators (apex to a point of its foot)
// along which the view rays graze it. The cone's tangent plane is the same all along a
// generator, so the rays graze it where that plane holds the eye: the roots in phi of
// ((B(phi) - A) x B'(phi)) . (E - A) = 0, A the apex, B(phi) the foot's point at azimuth phi from
// the axis, E the eye.
#pragma once

#include <array>
#include <vector>

#include "proj_enu.h"
#include "synthetic_raster.h"

namespace maquette::test {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b);
double dot(const Vec& a, const Vec& b);
double norm(const Vec& a);

class ConeView {
 public:
  ConeView(double eye_lon, double eye_lat, double eye_height);
  // The cone's surface `r` metres from its axis at `azimuth` (radians clockwise from grid north).
  Vec at(double azimuth, double r) const;
  Vec apex() const { return at(0, 0); }
  // The azimuths of the two tangent generators' feet, ascending (fails the test unless two).
  std::vector<double> tangent_azimuths() const;

 private:
  double tangency(double phi) const;
  ProjEnu enu_;
  Projector lonlat_{"EPSG:32612", "EPSG:4326"};
  std::array<double, 2> axis_;
};

}  // namespace maquette::test
