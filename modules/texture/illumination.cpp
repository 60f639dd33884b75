#include "illumination.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "runtime/params_schema.h"

namespace maquette::texture {

std::array<float, 3> Illumination::corrected(std::array<float, 3> rgb, int c, int r) const {
  const float h = hillshade->at(c, r);
  if (std::isnan(h)) return rgb;
  const double cos_i = std::max((double(h) - 1) / 254, min_cos);
  const double top = std::max({rgb[0], rgb[1], rgb[2]});
  double f = (flat_cos + c_correction) / (cos_i + c_correction);
  if (top > 0) f = std::min(f, 255 / top);
  for (float& v : rgb) v = float(v * f);
  return rgb;
}

nlohmann::json illumination_params_schema() {
  return {{"sun_altitude",
           number_param(0, 90, 0,
                        "degrees: the image's sun altitude; > 0 scales each pixel's colour by "
                        "sin(altitude) / max(cos i, min_incidence_cos), i the incidence angle "
                        "from inputs.hillshade (cosine correction; 0: none)")},
          {"min_incidence_cos",
           number_param(0.01, 1, 0.2, "floor of cos i in the illumination correction")},
          {"c_correction",
           number_param(0, 10, 0,
                        "c of the C-correction: the factor becomes (sin(altitude) + c) / "
                        "(max(cos i, min_incidence_cos) + c), c the intercept / slope of the "
                        "scene's brightness regressed on cos i (0: the cosine correction)")}};
}

std::optional<Illumination> illumination_of(const nlohmann::json& params, const CellData& data,
                                            const std::string& op) {
  const double altitude = params.at("sun_altitude").get<double>();
  if (altitude <= 0) return std::nullopt;
  if (!data.inputs.count("hillshade"))
    throw Error(op + ": params.sun_altitude needs inputs.hillshade");
  return Illumination{&data.inputs.at("hillshade"), std::sin(altitude * std::numbers::pi / 180),
                      params.at("min_incidence_cos").get<double>(),
                      params.at("c_correction").get<double>()};
}

}  // namespace maquette::texture
