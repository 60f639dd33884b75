#include "core/ecef.h"

#include <GeographicLib/Geocentric.hpp>
#include <cmath>

namespace maquette {
namespace {

double radians(double degrees) { return degrees * (M_PI / 180); }

}  // namespace

Vec3 ecef(LonLat p, double height) {
  Vec3 r;
  GeographicLib::Geocentric::WGS84().Forward(p.lat, p.lon, height, r[0], r[1], r[2]);
  return r;
}

Vec3 east_unit(LonLat p) {
  const double lon = radians(p.lon);
  return {-std::sin(lon), std::cos(lon), 0};
}

Vec3 north_unit(LonLat p) {
  const double lon = radians(p.lon), lat = radians(p.lat);
  return {-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
}

Vec3 up_unit(LonLat p) {
  const double lon = radians(p.lon), lat = radians(p.lat);
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

}  // namespace maquette
