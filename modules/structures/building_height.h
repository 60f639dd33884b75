// A building's heights and roof from its OpenStreetMap tags.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace maquette::structures {

struct HeightRules {
  double default_height_m = 10;  // no usable height tag: the walls' height
  double level_height_m = 3;     // per building:levels and roof:levels
  double default_roof_angle_deg =
      30;  // a pitched roof without roof:height, roof:levels, roof:angle
};

// The roof shapes built (OSM `roof:shape`); any other value is built flat with a warning.
enum class RoofShape { Flat, Gabled, Hipped, Pyramidal, Skillion };
const char* roof_shape_name(RoofShape shape);

// What the tags say of a building before its footprint is known.
struct BuildingTags {
  std::optional<double> height;  // `height`: ground to the roof's top (m)
  double walls = 0;              // without `height`: building:levels x level height, or the default
  RoofShape roof = RoofShape::Flat;
  std::optional<double> roof_height;    // roof:height, else roof:levels x level height (m)
  double roof_angle_deg = 0;            // roof:angle, else the rules' default
  bool angle_tagged = false;            // roof:angle given
  double default_roof_cap_m = 0;        // a roof of the default angle is at most this high
  std::optional<double> direction_deg;  // roof:direction: where the main face looks, clockwise
                                        // from north (degrees or N, NNE, ... NNW)
  bool across = false;                  // roof:orientation=across: the ridge along the short axis
  std::string warning;                  // a roof:shape not modelled (built flat), for the user
};

// Reads `height` (metres: a number, or a string such as "12.5" or "12.5 m"), `building:levels`,
// `roof:shape`, `roof:height`, `roof:levels` (0 or absent: no roof levels), `roof:angle` (0..90
// degrees, exclusive), `roof:direction`, `roof:orientation` (along or across). A `roof:shape` of
// flat, gabled, hipped, pyramidal or skillion is built; any other is built flat and named in
// `warning`. Throws InvalidFootprint naming the tag and its value when one present cannot be read.
BuildingTags building_tags(const nlohmann::json& attributes, const HeightRules& rules);

// A part's wall top and roof height (m above the base).
struct PartHeights {
  double wall = 0, roof = 0;
  double top() const { return wall + roof; }
};

// The heights of a part whose roof rises over `run_m` (the horizontal distance from an eave to the
// roof's top, roof_planes.h): the roof's height is roof:height or roof:levels when tagged, else
// tan(roof:angle) x run, else tan(the default angle) x run up to one level (a large block's
// untagged roof stays a level high: 3 m over a 60 m block, not 17). With `height`, the walls end
// that far below it (a roof height from the angle capped at half the height: walls at least half
// the building); without, the walls are `walls` high and the roof sits on them (OSM's
// building:levels counts the levels below the roof). A flat roof has no height. Throws
// InvalidFootprint when a tagged roof height is not below `height`.
PartHeights part_heights(const BuildingTags& tags, double run_m);

}  // namespace maquette::structures
