// A building's height from its OpenStreetMap tags.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::structures {

struct HeightRules {
  double default_height_m = 10;  // no usable tag
  double level_height_m = 3;     // per building:levels
};

// `height` (metres: a number, or a string such as "12.5" or "12.5 m"), else `building:levels`
// x level_height_m, else default_height_m. `roof:shape` other than "flat" is left to later
// roof shapes: every roof is flat (LoD1), at the height. Throws InvalidFootprint naming the
// tag and its value when present but neither a positive number nor such a string.
double building_height(const nlohmann::json& attributes, const HeightRules& rules);

}  // namespace maquette::structures
