#include "image/hillshade.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace maquette {
namespace {

constexpr double kAuthalicRadius = 6371007.180918;  // metres per radian, close enough for shading

}  // namespace

std::vector<float> hillshade(const PictureRaster& m) {
  const PictureFrame& f = m.frame.value();
  const double azimuth = 315.0 * std::numbers::pi / 180.0, altitude = std::numbers::pi / 4;
  // Unit vector towards the sun: x east, y north, z up.
  const double sx = std::cos(altitude) * std::sin(azimuth),
               sy = std::cos(altitude) * std::cos(azimuth);
  const double sz = std::sin(altitude);
  const bool lonlat = f.projection == Projection::LonLat;
  const double radians = lonlat ? std::numbers::pi / 180.0 : 0.0;
  const double dy = lonlat ? f.y_step * radians * kAuthalicRadius : f.y_step;

  std::vector<float> out(size_t(m.width) * size_t(m.height),
                         std::numeric_limits<float>::quiet_NaN());
  for (int r = 0; r < m.height; ++r) {
    const double lat = (f.top - (r + 0.5) * f.y_step) * radians;
    const double dx =
        lonlat ? std::max(f.x_step * radians * kAuthalicRadius * std::cos(lat), 1e-3 * dy)
               : f.x_step;
    for (int c = 0; c < m.width; ++c) {
      const float z0 = m.at(c, r);
      if (!std::isfinite(z0)) continue;
      auto z = [&](int dc, int dr) {
        const int cc = c + dc, rr = r + dr;
        if (cc < 0 || rr < 0 || cc >= m.width || rr >= m.height) return double(z0);
        const float v = m.at(cc, rr);
        return std::isfinite(v) ? double(v) : double(z0);
      };
      // Horn: weighted differences; rows grow southwards, so north is -dr.
      const double dzdx =
          ((z(1, -1) + 2 * z(1, 0) + z(1, 1)) - (z(-1, -1) + 2 * z(-1, 0) + z(-1, 1))) / (8 * dx);
      const double dzdy =
          ((z(-1, -1) + 2 * z(0, -1) + z(1, -1)) - (z(-1, 1) + 2 * z(0, 1) + z(1, 1))) / (8 * dy);
      // Normal (-dz/dx, -dz/dy, 1) normalised, dotted with the sun.
      const double shade = (-dzdx * sx - dzdy * sy + sz) / std::sqrt(dzdx * dzdx + dzdy * dzdy + 1);
      out[size_t(r) * size_t(m.width) + size_t(c)] = float(std::clamp(shade, 0.0, 1.0));
    }
  }
  return out;
}

}  // namespace maquette
