// maquette-paint's params (a JSON file): synthesis.transfer's exemplar and synthesis params with
// the same keys (transfer_params.h), and what the picture adds: the distance and light guides,
// the sky, the coherence breaks at silhouettes, the blend with the render's shading (README:
// maquette-paint).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "synthesis.h"

namespace maquette::synthesis {

struct PaintParams {
  std::string source;                                   // the params' file, which errors name
  nlohmann::json exemplar;                              // the validated params: transfer_exemplar's
  std::map<int, uint8_t> classes;                       // land-cover value -> painting class
  std::optional<std::array<double, 2>> altitude_range;  // metres -> 0..1
  std::optional<std::array<double, 2>> distance_range;  // metres from the eye -> 0..1 (log)
  std::optional<uint8_t> sky_class;  // the sky painted from this class, else kept
  bool silhouettes = true;           // coherence breaks where the depth jumps (depth_break)
  double shading = 0;                // strength of the blend with the render's shading, 0..1
  double haze_distance = 0;          // metres of aerial perspective (painted_haze.h); 0: none
  std::optional<std::array<uint8_t, 3>> haze_color;  // sRGB; none: the painted sky's mean
  int tile = 256;                                    // output pixels a side synthesized at once
  SynthesisParams synthesis;
};

// JSON Schema of the file (the draft 7 subset of framework/runtime/params_schema.h).
nlohmann::json paint_params_schema();

// The params from `raw` (read from `source`, which errors name): validated, defaults filled,
// each guide's two halves given together (altitude_range with painting_altitude,
// distance_range with painting_distance; w_distance not without them, w_light not without
// painting_light, which is not "rows"; labels, painting_altitude and painting_distance
// "guides" not without painting_guides, nor it without one of them), sky_class not excluded
// and in no land-cover class's value of landcover_classes (the sky is a class of its own),
// haze_color not without haze_distance.
PaintParams paint_params(const nlohmann::json& raw, const std::string& source);

// Distance from the eye mapped onto the range logarithmically (perspective shrinks the far
// country as 1 / distance): 0 at low, 1 at high, clamped; NaN stays NaN.
float distance_guide(float metres, const std::array<double, 2>& range);

}  // namespace maquette::synthesis
