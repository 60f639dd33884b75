// The scene's illumination removed from its colours (albedo): the C-correction (the cosine
// correction when c is 0) shared by
// texture.cluster, texture.classify, texture.fit and texture.assess, so that classes, fitted
// colours and the assessment all see the same unshaded scene.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "runtime/operator.h"

namespace maquette::texture {

struct Illumination {
  const Tile<float>* hillshade = nullptr;  // terrain.derive's hillshade at the scene's sun
  double flat_cos = 1;                     // sin(sun altitude): the incidence on flat ground
  double min_cos = 0.2;                    // floor of cos i
  double c_correction = 0;                 // the C-correction's c (0: the cosine correction)

  // Colour of a pixel lit at incidence cos i (hillshade h = 1 + 254 cos i) as it would look on
  // flat ground, brightness taken as proportional to cos i + c (Teillet et al. 1982: c the
  // intercept / slope of the regression of brightness on cos i; diffuse light and the
  // non-Lambertian canopy make shaded slopes brighter than cos i alone says, so c = 0
  // over-corrects them): scaled by (flat_cos + c) / (max(cos i, min_cos) + c), at most what
  // keeps every channel <= 255, so hue and saturation are unchanged. Unknown illumination (NaN)
  // leaves it as is.
  std::array<float, 3> corrected(std::array<float, 3> rgb, int c, int r) const;

  // Whether the pixel is lit at cos i >= `lit_cos` (always when lit_cos <= 0; never when its
  // illumination is unknown otherwise): a class's colour statistics from lit pixels only, since
  // shaded slopes keep a grey the correction does not remove on a coarse DEM.
  bool lit(int c, int r, double lit_cos) const;
};

// The parameters "sun_altitude" (degrees, 0: no correction), "min_incidence_cos" and
// "c_correction".
nlohmann::json illumination_params_schema();

// The parameter "colour_min_incidence_cos" of texture.fit and texture.assess: a class's colour
// (mean and spread) from the pixels lit at cos i >= it only (0: every pixel).
nlohmann::json colour_incidence_param();

// Its value; throws naming `op` when it is > 0 without an illumination (sun_altitude 0).
double colour_incidence(const nlohmann::json& params, const std::optional<Illumination>& light,
                        const std::string& op);

// Throws naming `op` when params.sun_altitude asks for the correction and inputs.hillshade is not
// mapped: an operator's check_params, told when the pipeline is read.
void check_illumination_params(const nlohmann::json& params, bool hillshade_mapped,
                               const std::string& op);

// The correction asked for by params, reading inputs.hillshade; nullopt when sun_altitude is 0.
// Throws naming `op` when the hillshade input is not mapped.
std::optional<Illumination> illumination_of(const nlohmann::json& params, const CellData& data,
                                            const std::string& op);

}  // namespace maquette::texture
