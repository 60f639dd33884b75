// Round strokes for tests: a circle on the ground as a closed GeoJSON ring.
#pragma once

#include <nlohmann/json.hpp>

namespace maquette::test {

// `points` points evenly spaced on the circle of `radius_m` metres around (lon, lat) in the
// tangent plane there (GeographicLib::LocalCartesian), counter-clockwise from east, then the first
// again: the coordinates of a GeoJSON ring ([lon, lat] each).
nlohmann::json circle_ring(double lon, double lat, double radius_m, int points);

}  // namespace maquette::test
