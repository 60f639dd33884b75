#include "synthetic_painting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "proj_enu.h"

namespace maquette::test {

double synthetic_terrain(double lon, double lat) {
  return 400 + 900 * std::pow(std::sin(lon * 37) * std::cos(lat * 29), 2) +
         300 * std::sin(lon * 113 + lat * 71);
}

std::optional<std::array<double, 2>> SyntheticPainting::pixel(const ProjEnu& enu,
                                                              const GeodeticPoint& ground) const {
  auto p = enu({ground.lon, ground.lat}, ground.height);
  if (bend_radius > 0)
    p = bent(p, bend_radius, bend_start, synthetic_terrain(eye_lon, eye_lat) - eye_height);
  const Matrix3 r = camera.rotation();
  if (r[2][0] * p[0] + r[2][1] * p[1] + r[2][2] * p[2] <= 0) return std::nullopt;
  const auto px = camera.project(p);
  double x = px[0] + 0.5, y = px[1] + 0.5;  // OpenCV's pixel centres are at integers
  if (bulge != 0) {
    const double s = camera.width / 6.0, dx = x - camera.width * 0.5, dy = y - camera.height * 0.5;
    const double push = bulge * std::exp(-(dx * dx + dy * dy) / (2 * s * s)) / s;
    x += push * dx;
    y += push * dy;
  }
  if (x < 0 || y < 0 || x > camera.width || y > camera.height) return std::nullopt;
  return std::array<double, 2>{x, y};
}

std::vector<GroundClick> SyntheticPainting::clicks(size_t count, double noise,
                                                   std::mt19937& random) const {
  std::uniform_real_distribution<double> lon(west, east), lat(south, north);
  std::normal_distribution<double> error(0, noise / std::sqrt(2.0));
  const ProjEnu enu(eye_lon, eye_lat, eye_height);
  std::vector<GroundClick> out;
  while (out.size() < count) {
    GeodeticPoint g{lon(random), lat(random), 0};
    g.height = synthetic_terrain(g.lon, g.lat);
    const auto px = pixel(enu, g);
    if (!px) continue;
    const double dx = noise > 0 ? error(random) : 0, dy = noise > 0 ? error(random) : 0;
    out.push_back({(*px)[0] + dx, (*px)[1] + dy, g});
  }
  return out;
}

SyntheticPainting plain_painting() {
  SyntheticPainting p;
  p.eye_lon = 10.2;
  p.eye_lat = 44.9;
  p.eye_height = 3000;
  p.camera = {8, -12, 55, 1600, 1000};
  p.west = 9.9;
  p.east = 10.5;
  p.south = 44.93;
  p.north = 45.4;
  return p;
}

SyntheticPainting bent_painting() {
  SyntheticPainting p = plain_painting();
  p.eye_height = 2000;
  p.camera = {5, -6, 60, 1600, 1000};
  p.bend_radius = 35000;
  p.bend_start = 6000;
  p.north = 45.45;
  return p;
}

std::array<double, 2> error_percentiles(const SyntheticPainting& painting,
                                        const std::vector<GroundClick>& truth,
                                        const std::vector<std::array<double, 2>>& fitted) {
  const ProjEnu enu(painting.eye_lon, painting.eye_lat, painting.eye_height);
  std::vector<double> errors;
  for (size_t i = 0; i < truth.size(); ++i) {
    const auto px = painting.pixel(enu, truth[i].ground);
    const double e = std::hypot(fitted[i][0] - (*px)[0], fitted[i][1] - (*px)[1]);
    errors.push_back(std::isnan(e) ? std::numeric_limits<double>::infinity() : e);  // behind
  }
  std::sort(errors.begin(), errors.end());
  const auto at = [&](double q) { return errors[size_t(q * double(errors.size() - 1) + 0.5)]; };
  return {at(0.5), at(0.9)};
}

}  // namespace maquette::test
