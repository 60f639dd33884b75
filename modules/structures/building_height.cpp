#include "building_height.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

#include "footprint.h"

namespace maquette::structures {
namespace {

const nlohmann::json* tag(const nlohmann::json& attributes, const char* name) {
  const auto it = attributes.find(name);
  return it == attributes.end() || it->is_null() ? nullptr : &*it;
}

[[noreturn]] void bad_tag(const char* name, const nlohmann::json& value, const char* expected) {
  throw InvalidFootprint(std::string("tag ") + name + " = " + value.dump() + " is not " + expected);
}

// A tag's number: a JSON number, or a string of one with an optional " m"; NaN when neither.
double number_of(const nlohmann::json& value) {
  if (value.is_number()) return value.get<double>();
  if (!value.is_string()) return NAN;
  const std::string& text = value.get_ref<const std::string&>();
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const std::string rest(end);
  return end == text.c_str() || (!rest.empty() && rest != " m" && rest != "m") ? NAN : v;
}

// The positive number of a tag (absent: nullopt; 0 too when `zero_is_absent`).
std::optional<double> positive_tag(const nlohmann::json& attributes, const char* name,
                                   bool zero_is_absent = false) {
  const nlohmann::json* value = tag(attributes, name);
  if (!value) return std::nullopt;
  const double v = number_of(*value);
  if (zero_is_absent && v == 0) return std::nullopt;
  if (!(v > 0) || !std::isfinite(v))
    bad_tag(name, *value, "a positive number (of metres or levels)");
  return v;
}

std::optional<double> direction_tag(const nlohmann::json& attributes) {
  const nlohmann::json* value = tag(attributes, "roof:direction");
  if (!value) return std::nullopt;
  static const std::array<const char*, 16> kPoints = {"N",  "NNE", "NE", "ENE", "E",  "ESE",
                                                      "SE", "SSE", "S",  "SSW", "SW", "WSW",
                                                      "W",  "WNW", "NW", "NNW"};
  if (value->is_string())
    for (size_t k = 0; k < kPoints.size(); ++k)
      if (value->get_ref<const std::string&>() == kPoints[k]) return 22.5 * double(k);
  const double v = number_of(*value);
  if (!std::isfinite(v))
    bad_tag("roof:direction", *value, "degrees or a compass point (N, NNE...)");
  return v;
}

}  // namespace

const char* roof_shape_name(RoofShape shape) {
  switch (shape) {
    case RoofShape::Gabled:
      return "gabled";
    case RoofShape::Hipped:
      return "hipped";
    case RoofShape::Pyramidal:
      return "pyramidal";
    case RoofShape::Skillion:
      return "skillion";
    case RoofShape::Flat:
      break;
  }
  return "flat";
}

BuildingTags building_tags(const nlohmann::json& attributes, const HeightRules& rules) {
  BuildingTags t;
  t.height = positive_tag(attributes, "height");
  const std::optional<double> levels = positive_tag(attributes, "building:levels");
  t.walls = levels ? *levels * rules.level_height_m : rules.default_height_m;
  if (const nlohmann::json* shape = tag(attributes, "roof:shape")) {
    const std::string name = shape->is_string() ? shape->get<std::string>() : shape->dump();
    bool known = false;
    for (const RoofShape s : {RoofShape::Flat, RoofShape::Gabled, RoofShape::Hipped,
                              RoofShape::Pyramidal, RoofShape::Skillion})
      if (name == roof_shape_name(s)) t.roof = s, known = true;
    if (!known) t.warning = "roof:shape = " + shape->dump() + " is not modelled: built flat";
  }
  t.roof_height = positive_tag(attributes, "roof:height");
  if (!t.roof_height)
    if (const auto roof_levels = positive_tag(attributes, "roof:levels", true))
      t.roof_height = *roof_levels * rules.level_height_m;
  t.roof_angle_deg = rules.default_roof_angle_deg;
  t.default_roof_cap_m = rules.level_height_m;
  if (const nlohmann::json* angle = tag(attributes, "roof:angle")) {
    t.angle_tagged = true;
    t.roof_angle_deg = number_of(*angle);
    if (!(t.roof_angle_deg > 0 && t.roof_angle_deg < 90))
      bad_tag("roof:angle", *angle, "an angle between 0 and 90 degrees");
  }
  t.direction_deg = direction_tag(attributes);
  if (const nlohmann::json* orientation = tag(attributes, "roof:orientation")) {
    if (*orientation != "along" && *orientation != "across")
      bad_tag("roof:orientation", *orientation, "along or across");
    t.across = *orientation == "across";
  }
  return t;
}

PartHeights part_heights(const BuildingTags& tags, double run_m) {
  if (tags.roof == RoofShape::Flat) return {tags.height.value_or(tags.walls), 0};
  double from_angle = std::tan(tags.roof_angle_deg * std::numbers::pi / 180) * run_m;
  if (!tags.angle_tagged) from_angle = std::min(from_angle, tags.default_roof_cap_m);
  if (!tags.height) return {tags.walls, tags.roof_height.value_or(from_angle)};
  if (tags.roof_height && *tags.roof_height >= *tags.height) {
    std::ostringstream m;
    m << "the roof's height " << *tags.roof_height << " m (roof:height or roof:levels) is not below"
      << " the tag height = " << *tags.height << " m";
    throw InvalidFootprint(m.str());
  }
  const double roof = tags.roof_height.value_or(std::min(from_angle, *tags.height / 2));
  return {*tags.height - roof, roof};
}

}  // namespace maquette::structures
