#include "core/enu_frame.h"

#include <GeographicLib/LocalCartesian.hpp>
#include <vector>

namespace maquette {

EnuFrame::EnuFrame(const GeodeticPoint& origin)
    : frame_(std::make_shared<const GeographicLib::LocalCartesian>(origin.lat, origin.lon,
                                                                   origin.height)) {}

std::array<double, 3> EnuFrame::to_enu(double lon, double lat, double height) const {
  std::array<double, 3> p;
  frame_->Forward(lat, lon, height, p[0], p[1], p[2]);
  return p;
}

std::array<double, 3> EnuFrame::to_enu(double lon, double lat, double height,
                                       std::array<double, 9>& axes) const {
  std::array<double, 3> p;
  thread_local std::vector<double> m(axes.size());  // Forward's matrix: no allocation per point
  frame_->Forward(lat, lon, height, p[0], p[1], p[2], m);
  std::copy(m.begin(), m.end(), axes.begin());
  return p;
}

GeodeticPoint EnuFrame::to_geodetic(double x, double y, double z) const {
  GeodeticPoint p;
  frame_->Reverse(x, y, z, p.lat, p.lon, p.height);
  return p;
}

}  // namespace maquette
