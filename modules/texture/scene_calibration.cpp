#include "scene_calibration.h"

#include <algorithm>
#include <cmath>

#include "core/srgb.h"

namespace maquette::texture {

double SceneCalibration::reflectance(int band, double dn) const {
  const BandCalibration& b = bands[size_t(band)];
  return (b.mult * dn + b.add) / std::sin(sun_elevation_deg * M_PI / 180);
}

void SceneCalibration::set_haze_from_dark_object(int band, double dark_dn,
                                                 double dark_reflectance) {
  bands[size_t(band)].haze = reflectance(band, dark_dn) - dark_reflectance;
}

float SceneCalibration::display(int band, float dn) const {
  if (std::isnan(dn)) return dn;
  const double linear = (reflectance(band, dn) - bands[size_t(band)].haze) / white;
  return float(std::clamp(std::round(srgb_from_linear(linear)), 1.0, 255.0));
}

}  // namespace maquette::texture
