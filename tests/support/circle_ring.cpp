#include "circle_ring.h"

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <numbers>

namespace maquette::test {

nlohmann::json circle_ring(double lon, double lat, double radius_m, int points) {
  const GeographicLib::LocalCartesian centre(lat, lon, 0);
  nlohmann::json ring = nlohmann::json::array();
  for (int k = 0; k <= points; ++k) {
    const double t = 2 * std::numbers::pi * (k % points) / points;
    double p_lat = 0, p_lon = 0, h = 0;
    centre.Reverse(radius_m * std::cos(t), radius_m * std::sin(t), 0, p_lat, p_lon, h);
    ring.push_back({p_lon, p_lat});
  }
  return ring;
}

}  // namespace maquette::test
