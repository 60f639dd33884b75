#include "horizon.h"

#include <cmath>

namespace maquette::climate {

HorizonAngles::HorizonAngles(int directions, double max_distance_m)
    : directions_(directions), max_distance_(max_distance_m) {}

void HorizonAngles::compute(const Tile<float>& dem, const PixelFrame& frame, int col, int row,
                            double z0, std::vector<double>& out) const {
  out.assign(size_t(directions_), -M_PI / 2);
  for (int k = 0; k < directions_; ++k) {
    const March m = march(frame, 360.0 * k / directions_);
    double best_tan = -INFINITY;  // tangent of the highest elevation angle so far
    for (int step = 1; step * m.metres <= max_distance_; ++step) {
      const double z = bilinear(dem, col + step * m.dcol, row + step * m.drow);
      if (std::isnan(z)) break;  // beyond the halo or no data
      const double d = step * m.metres;
      const double t = (z - d * d / (2 * kEarthRadius) - z0) / d;
      if (t > best_tan) best_tan = t;
    }
    out[size_t(k)] = std::atan(best_tan);  // atan(-inf) = -pi/2
  }
}

double HorizonAngles::at(const std::vector<double>& angles, double azimuth) const {
  double x = azimuth / (2 * M_PI) * directions_;
  x -= std::floor(x / directions_) * directions_;
  const int i = int(x) % directions_;
  const double t = x - std::floor(x);
  return (1 - t) * angles[size_t(i)] + t * angles[size_t((i + 1) % directions_)];
}

}  // namespace maquette::climate
