// Moving content between two east-north-up frames (content.h, EnuOrigin): both are rigid
// frames of ECEF, so a point's coordinates in one map to the other by a rotation and a
// translation, computed here in double precision from the two origins (core/ecef.h). One frame's
// own points to and from geodetic coordinates: core/enu_frame.h.
#pragma once

#include <array>

#include "content/content.h"
#include "core/enu_frame.h"

namespace maquette {

class EnuTransform {
 public:
  EnuTransform(const EnuOrigin& from, const EnuOrigin& to);
  // A point of the `from` frame in the `to` frame (metres), in double.
  std::array<double, 3> point(double x, double y, double z) const;
  // A direction (no translation), e.g. a normal.
  std::array<double, 3> direction(double x, double y, double z) const;
  // A rotation of the `from` frame (unit quaternion x, y, z, w, glTF order) as the same
  // rotation of the `to` frame: the frames' rotation composed before it.
  std::array<double, 4> rotation(double x, double y, double z, double w) const;
  // 4x4 row-major matrix of `point` (last row 0 0 0 1), for libraries taking affine maps.
  std::array<double, 16> matrix() const;

 private:
  std::array<std::array<double, 3>, 3> rotation_{};  // rows: to's axes in from's frame
  std::array<double, 3> translation_{};
};

// The east-north-up frame at a content's origin (core/enu_frame.h), for its points' geodetic
// coordinates and back.
inline EnuFrame enu_frame(const EnuOrigin& o) { return EnuFrame({o.lon, o.lat, o.height}); }

}  // namespace maquette
