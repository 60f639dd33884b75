#include "paint_params.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/error.h"
#include "runtime/params_schema.h"
#include "transfer_params.h"

namespace maquette::synthesis {

nlohmann::json paint_params_schema() {
  using json = nlohmann::json;
  json properties = exemplar_params_schema();
  properties.update(synthesis_params_schema());
  // The painting's masks may come from its guides (painting_guides.h).
  for (const auto& [field, band] : {std::pair{"labels", "land_cover through landcover_classes"},
                                    std::pair{"painting_altitude", "altitude"}}) {
    auto& description = properties[field]["description"];
    description = description.get<std::string>() + "; or \"guides\": painting_guides' " + band;
  }
  properties.update(
      {{"painting_guides",
        {{"type", "string"},
         {"description",
          "the painting's guides: a float GeoTIFF of its size as render fit --panorama (or render "
          "panorama) writes it, its bands by name; read for labels, painting_altitude and "
          "painting_distance given as \"guides\""}}},
       {"painting_distance",
        {{"type", "string"},
         {"description",
          "the painting's distance from its viewer: a grey image (its size, white far), "
          "\"rows\" (far at the top), or \"guides\": painting_guides' distance"}}},
       {"distance_range",
        {{"type", "array"},
         {"items", {{"type", "number"}}},
         {"description", "[near, far] metres from the eye mapped to distance 0..1 (log)"}}},
       {"w_distance", {{"type", "number"}, {"minimum", 0}, {"default", 1.0}}},
       {"painting_light",
        {{"type", "string"},
         {"description",
          "the painting's light: \"lightness\" (each pixel's L* as its quantile within its "
          "class), or a grey image (its size, white light; its values as quantiles within each "
          "class too)"}}},
       {"w_light",
        {{"type", "number"},
         {"minimum", 0},
         {"default", 0.0},
         {"description",
          "weight of the light mismatch: the painting's light against the quantile of the "
          "render's shading within each class (with painting_light)"}}},
       {"sky_class",
        {{"type", "integer"},
         {"minimum", 0},
         {"maximum", 254},
         {"description", "painting class the sky is painted from (else the render's sky)"}}},
       {"silhouettes",
        {{"type", "boolean"},
         {"default", true},
         {"description", "no coherent copy across a depth break (the render's silhouettes)"}}},
       {"depth_break",
        {{"type", "number"},
         {"minimum", 1},
         {"default", 1.05},
         {"description", "a neighbour farther by this factor is across a silhouette"}}},
       {"shading",
        {{"type", "number"},
         {"minimum", 0},
         {"maximum", 1},
         {"default", 0.7},
         {"description", "strength of the blend with the render's shading"}}},
       {"haze_distance",
        {{"type", "number"},
         {"minimum", 0},
         {"default", 0.0},
         {"description",
          "aerial perspective: metres at which the painted terrain is 63 % haze (1 - "
          "exp(-distance / haze_distance), mixed in linear light); 0: none"}}},
       {"haze_color",
        {{"type", "array"},
         {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", 255}}},
         {"description",
          "the haze's colour, 8-bit sRGB [r, g, b] (with haze_distance; default: the mean, in "
          "linear light, of the painted picture's sky)"}}},
       {"tile",
        {{"type", "integer"},
         {"minimum", 16},
         {"maximum", 4096},
         {"default", 256},
         {"description", "output pixels a side synthesized at once (the same bits for any)"}}}});
  return {{"type", "object"},
          {"additionalProperties", false},
          {"required", {"painting", "landcover_classes"}},
          {"properties", properties}};
}

PaintParams paint_params(const nlohmann::json& raw, const std::string& source) {
  PaintParams p;
  p.source = source;
  p.exemplar = validate_params(paint_params_schema(), raw, source);
  const nlohmann::json& j = p.exemplar;
  p.classes = class_table(j.at("landcover_classes"), source);
  for (const auto& [range, guide] : {std::pair{"altitude_range", "painting_altitude"},
                                     std::pair{"distance_range", "painting_distance"}})
    if (j.contains(range) != j.contains(guide))
      throw Error(source + ": " + (j.contains(range) ? range : guide) + " is given without " +
                  (j.contains(range) ? guide : range) + ": give both or neither");
  if (raw.contains("w_distance") && !j.contains("distance_range"))
    throw Error(source + ": w_distance is given without distance_range and painting_distance");
  if (raw.contains("w_light") && !j.contains("painting_light"))
    throw Error(source + ": w_light is given without painting_light");
  // The painting's guides with a use, and a use with the guides: neither passes silently.
  bool guided = false;
  for (const char* field : {"labels", "painting_altitude", "painting_distance"})
    if (j.contains(field) && j.at(field) == "guides") {
      if (!j.contains("painting_guides"))
        throw Error(source + "." + field +
                    ": \"guides\" is given without painting_guides (the painting's guides file, "
                    "as render fit --panorama writes it)");
      guided = true;
    }
  if (j.contains("painting_guides") && !guided)
    throw Error(source +
                ".painting_guides: given, but none of labels, painting_altitude and "
                "painting_distance is \"guides\": it would be read for nothing");
  if (j.contains("painting_light") && j.at("painting_light") == "rows")
    throw Error(source + ".painting_light: \"rows\" is no light: \"lightness\" or a grey image");
  if (j.contains("altitude_range")) p.altitude_range = range_param(j, "altitude_range", source);
  if (j.contains("distance_range"))
    p.distance_range = range_param(j, "distance_range", source, true);
  if (j.contains("sky_class")) {
    const int sky = j.at("sky_class").get<int>();
    const auto excluded = j.at("exclude_classes").get<std::vector<int>>();
    if (std::find(excluded.begin(), excluded.end(), sky) != excluded.end())
      throw Error(source + ".sky_class: class " + std::to_string(sky) +
                  " is in exclude_classes: the sky could never be copied from it");
    // The sky is a class of its own: a class that paints land cover too would copy the sky's
    // pixels onto the land and the land's into the sky.
    for (const auto& [key, value] : j.at("landcover_classes").items())
      if (value == sky ||
          (value.is_array() && std::find(value.begin(), value.end(), sky) != value.end()))
        throw Error(source + ".sky_class: class " + std::to_string(sky) +
                    " also paints land-cover class " + key +
                    " (landcover_classes): the sky must be a class of its own");
    p.sky_class = uint8_t(sky);
  }
  p.silhouettes = j.at("silhouettes").get<bool>();
  p.shading = j.at("shading").get<double>();
  p.haze_distance = j.at("haze_distance").get<double>();
  if (j.contains("haze_color")) {
    if (p.haze_distance == 0)
      throw Error(source + ".haze_color: given without haze_distance: it would colour nothing");
    const auto c = j.at("haze_color").get<std::vector<int>>();
    if (c.size() != 3)
      throw Error(source + ".haze_color: " + j.at("haze_color").dump() +
                  " is not 3 numbers (8-bit red, green, blue)");
    p.haze_color = std::array<uint8_t, 3>{uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2])};
  }
  p.tile = j.at("tile").get<int>();
  p.synthesis = synthesis_params(j);
  p.synthesis.w_distance = p.distance_range ? j.at("w_distance").get<double>() : 0.0;
  p.synthesis.w_light = j.at("w_light").get<double>();
  p.synthesis.depth_break = j.at("depth_break").get<double>();
  return p;
}

float distance_guide(float metres, const std::array<double, 2>& range) {
  if (std::isnan(metres)) return metres;
  const double t =
      std::log(std::max(double(metres), range[0]) / range[0]) / std::log(range[1] / range[0]);
  return float(std::min(t, 1.0));
}

}  // namespace maquette::synthesis
