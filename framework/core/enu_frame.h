// The east-north-up frame of the WGS84 ellipsoid at an origin: x east, y north, z up along the
// ellipsoid's normal at the origin, metres, the origin at (0, 0, 0). Geodetic points go to the
// frame and back exactly (GeographicLib::LocalCartesian: through ECEF, no series), so every
// operator, module and exporter that places or measures things in a local tangent plane shares
// this one transform. The frame is set up once for many points; copies share it (immutable, safe
// across threads).
#pragma once

#include <array>
#include <memory>

namespace GeographicLib {
class LocalCartesian;
}

namespace maquette {

// A point given by its geodetic coordinates on WGS84.
struct GeodeticPoint {
  double lon = 0, lat = 0;  // degrees
  double height = 0;        // metres above the ellipsoid
  bool operator==(const GeodeticPoint&) const = default;
};

class EnuFrame {
 public:
  // The frame at `origin` (latitude in [-90, 90]).
  explicit EnuFrame(const GeodeticPoint& origin);

  // The point at (lon, lat, height) in the frame (x, y, z metres).
  std::array<double, 3> to_enu(double lon, double lat, double height = 0) const;
  // The same, and `axes`: the point's own east-north-up axes in the frame, row-major (column j
  // is the point's axis j), the rotation from the point's frame to this one.
  std::array<double, 3> to_enu(double lon, double lat, double height,
                               std::array<double, 9>& axes) const;
  // The geodetic coordinates of the frame's point (x, y, z metres).
  GeodeticPoint to_geodetic(double x, double y, double z) const;

 private:
  std::shared_ptr<const GeographicLib::LocalCartesian> frame_;
};

}  // namespace maquette
