#include "prism_strokes.h"

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "core/error.h"
#include "core/json_file.h"

namespace maquette::structures {
namespace {

using json = nlohmann::json;

Vec2 pixel(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number() ||
      !std::isfinite(j[0].get<double>()) || !std::isfinite(j[1].get<double>()))
    throw Error(where + " is not a pixel [x, y] of two finite numbers: " + j.dump());
  return {j[0].get<double>(), j[1].get<double>()};
}

double positive(const json& j, const std::string& where) {
  if (!j.is_number() || !(j.get<double>() > 0) || !std::isfinite(j.get<double>()))
    throw Error(where + " is not a positive number: " + j.dump());
  return j.get<double>();
}

int index(const json& j, const std::string& where) {
  if (!j.is_number_integer()) throw Error(where + " is not an integer: " + j.dump());
  return j.get<int>();
}

const json& field(const json& j, const char* name, const std::string& file) {
  if (!j.contains(name)) throw Error(file + ": field '" + name + "' is missing");
  return j[name];
}

}  // namespace

PrismStrokes read_prism_strokes(const std::string& path) {
  // Names the file and why it cannot be read, or the line and column where it is not JSON; refuses
  // nesting deeper than kMaxJsonDepth (quoting such a value in a message overflowed the stack).
  const json j = read_json_file(path);
  if (!j.is_object()) throw Error(path + ": not a JSON object");
  const std::set<std::string> known{"photo",     "focal_px",        "profile", "corner",
                                    "extrusion", "more_extrusions", "height_m"};
  for (const auto& [key, value] : j.items())
    if (!known.count(key)) throw Error(path + ": unknown field '" + key + "'");
  PrismStrokes s;
  const json& photo = field(j, "photo", path);
  if (!photo.is_string() || photo.get<std::string>().empty())
    throw Error(path + ": field 'photo' is not a file name: " + photo.dump());
  s.photo = (std::filesystem::path(path).parent_path() / photo.get<std::string>()).string();
  if (j.contains("focal_px")) s.focal_px = positive(j["focal_px"], path + ": field 'focal_px'");
  if (j.contains("height_m")) s.height_m = positive(j["height_m"], path + ": field 'height_m'");
  const json& profile = field(j, "profile", path);
  if (!profile.is_array())
    throw Error(path + ": field 'profile' is not an array of pixels: " + profile.dump());
  for (size_t i = 0; i < profile.size(); ++i)
    s.clicks.profile.push_back(pixel(profile[i], path + ": profile[" + std::to_string(i) + "]"));
  s.clicks.corner = index(field(j, "corner", path), path + ": field 'corner'");
  s.clicks.extrusion = pixel(field(j, "extrusion", path), path + ": field 'extrusion'");
  if (j.contains("more_extrusions")) {
    const json& more = j["more_extrusions"];
    if (!more.is_array())
      throw Error(path + ": field 'more_extrusions' is not an array: " + more.dump());
    for (size_t i = 0; i < more.size(); ++i) {
      const std::string where = path + ": more_extrusions[" + std::to_string(i) + "]";
      if (!more[i].is_object()) throw Error(where + " is not an object: " + more[i].dump());
      s.clicks.more_extrusions.push_back({index(field(more[i], "vertex", where), where + ".vertex"),
                                          pixel(field(more[i], "end", where), where + ".end")});
    }
  }
  return s;
}

}  // namespace maquette::structures
