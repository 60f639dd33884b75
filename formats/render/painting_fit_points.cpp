#include "render/painting_fit_points.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/json_file.h"

namespace maquette {
namespace {

using nlohmann::json;

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// Reads one field of `object` in the file `source`, at `where` ("points[3].lat").
class Fields {
 public:
  explicit Fields(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw Error(source_ + ": " + where + " " + what);
  }
  // Refuses a key of `object` not in `keys`: a misspelt "heigth" took the DEM's height silently.
  void known(const json& object, const std::string& where,
             std::initializer_list<const char*> keys) const {
    for (const auto& [key, _] : object.items())
      if (std::find_if(keys.begin(), keys.end(), [&](const char* k) { return key == k; }) ==
          keys.end()) {
        std::string list;
        for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
        fail(where, "has an unknown field \"" + key + "\" (expected: " + list + ")");
      }
  }
  const json* find(const json& object, const std::string& key) const {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }
  double number(const json& object, const std::string& key, const std::string& where) const {
    const json* v = find(object, key);
    if (!v) fail(where, "is missing");
    if (!v->is_number() || !std::isfinite(v->get<double>()))
      fail(where, v->dump() + " is not a finite number");
    return v->get<double>();
  }
  double in_range(const json& object, const std::string& key, const std::string& where, double lo,
                  double hi) const {
    const double v = number(object, key, where);
    if (!(v >= lo && v <= hi))
      fail(where,
           find(object, key)->dump() + " is outside [" + shortest(lo) + ", " + shortest(hi) + "]");
    return v;
  }

 private:
  std::string source_;
};

}  // namespace

PaintingPoints parse_painting_points(const std::string& text, const std::string& source) {
  const Fields fields(source);
  // Nesting deeper than kMaxJsonDepth is refused: quoting such a value overflowed the stack.
  const json root = parse_json(text, source);
  if (!root.is_object()) fields.fail("the top level", "is not an object");
  fields.known(root, "the top level", {"width", "height", "points"});
  PaintingPoints painting;
  for (const auto& [key, size] :
       {std::pair{"width", &painting.width}, {"height", &painting.height}}) {
    const double v = fields.in_range(root, key, key, 1, 65536);
    if (v != std::floor(v)) fields.fail(key, json(v).dump() + " is not a whole number of pixels");
    *size = int(v);
  }
  const json* points = fields.find(root, "points");
  if (!points) fields.fail("points", "is missing");
  if (!points->is_array()) fields.fail("points", "is not an array");
  for (size_t i = 0; i < points->size(); ++i) {
    const std::string where = "points[" + std::to_string(i) + "]";
    const json& p = (*points)[i];
    if (!p.is_object()) fields.fail(where, p.dump() + " is not an object");
    ControlPoint c;
    c.name = where;
    if (const json* name = fields.find(p, "name")) {
      if (!name->is_string()) fields.fail(where + ".name", name->dump() + " is not a string");
      c.name = where + " (" + name->get<std::string>() + ")";
    }
    fields.known(p, c.name, {"x", "y", "lon", "lat", "height", "name"});
    c.x = fields.in_range(p, "x", c.name + ".x", 0, painting.width);
    c.y = fields.in_range(p, "y", c.name + ".y", 0, painting.height);
    c.lon = fields.in_range(p, "lon", c.name + ".lon", -180, 180);
    c.lat = fields.in_range(p, "lat", c.name + ".lat", -90, 90);
    if (fields.find(p, "height")) c.height = fields.number(p, "height", c.name + ".height");
    painting.points.push_back(c);
  }
  if (painting.points.size() < 4)
    fields.fail("points", "has " + std::to_string(painting.points.size()) +
                              " points: the camera needs at least 4");
  return painting;
}

PaintingPoints read_painting_points(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_painting_points(text.str(), path);
}

}  // namespace maquette
