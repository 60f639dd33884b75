#include "building_height.h"

#include <cmath>
#include <cstdlib>

#include "footprint.h"

namespace maquette::structures {
namespace {

// The positive number of a tag: a JSON number, or a string of one with an optional " m".
double tag_number(const nlohmann::json& attributes, const char* tag, bool* present) {
  const auto it = attributes.find(tag);
  *present = it != attributes.end() && !it->is_null();
  if (!*present) return 0;
  double value = NAN;
  if (it->is_number()) {
    value = it->get<double>();
  } else if (it->is_string()) {
    const std::string& text = it->get_ref<const std::string&>();
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    const std::string rest(end);
    if (end == text.c_str() || (!rest.empty() && rest != " m" && rest != "m")) value = NAN;
  }
  if (!(value > 0) || !std::isfinite(value))
    throw InvalidFootprint(std::string("tag ") + tag + " = " + it->dump() +
                           " is not a positive number (of metres or levels)");
  return value;
}

}  // namespace

double building_height(const nlohmann::json& attributes, const HeightRules& rules) {
  bool present = false;
  if (const double h = tag_number(attributes, "height", &present); present) return h;
  if (const double levels = tag_number(attributes, "building:levels", &present); present)
    return levels * rules.level_height_m;
  return rules.default_height_m;
}

}  // namespace maquette::structures
