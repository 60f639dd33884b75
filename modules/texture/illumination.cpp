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

bool Illumination::lit(int c, int r, double lit_cos) const {
  return lit_cos <= 0 || (double(hillshade->at(c, r)) - 1) / 254 >= lit_cos;
}

nlohmann::json colour_incidence_param() {
  return {{"colour_min_incidence_cos",
           number_param(0, 1, 0,
                        "a class's colour (mean and spread) from the pixels lit at cos i >= "
                        "this only, i from inputs.hillshade as in the correction: the shaded "
                        "pixels' grey, which the correction on a coarse DEM leaves in, kept out "
                        "of the surface's colours (0: every pixel)")}};
}

double colour_incidence(const nlohmann::json& params, const std::optional<Illumination>& light,
                        const std::string& op) {
  const double lit_cos = params.at("colour_min_incidence_cos").get<double>();
  if (lit_cos > 0 && !light)
    throw Error(op + ": params.colour_min_incidence_cos needs params.sun_altitude > 0");
  return lit_cos;
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

void check_illumination_params(const nlohmann::json& params, bool hillshade_mapped,
                               const std::string& op) {
  if (params.at("sun_altitude").get<double>() > 0 && !hillshade_mapped)
    throw Error(op + ": params.sun_altitude needs inputs.hillshade");
}

std::optional<Illumination> illumination_of(const nlohmann::json& params, const CellData& data,
                                            const std::string& op) {
  check_illumination_params(params, data.inputs.count("hillshade") > 0, op);
  const double altitude = params.at("sun_altitude").get<double>();
  if (altitude <= 0) return std::nullopt;
  return Illumination{&data.inputs.at("hillshade"), std::sin(altitude * std::numbers::pi / 180),
                      params.at("min_incidence_cos").get<double>(),
                      params.at("c_correction").get<double>()};
}

}  // namespace maquette::texture
