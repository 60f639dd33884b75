#include "stations.h"

#include <fmt/format.h>

#include <cmath>

#include "core/error.h"

namespace maquette::climate {
namespace {

// The value as written, non-finite numbers included (JSON would print them as null).
std::string shown(const nlohmann::json& v) {
  return v.is_number() ? fmt::format("{}", v.get<double>()) : v.dump();
}

// A finite number within [lo, hi]; throws naming the station, the field and the value.
double coordinate(const nlohmann::json& s, const char* field, double lo, double hi,
                  const std::string& at) {
  if (!s.contains(field) || !s[field].is_number()) throw Error(at + ": no numeric '" + field + "'");
  const double v = s[field].get<double>();
  if (!std::isfinite(v) || v < lo || v > hi)
    throw Error(at + ": " + field + " " + shown(s[field]) + " is outside [" +
                std::to_string(int(lo)) + ", " + std::to_string(int(hi)) + "]");
  return v;
}

// A missing value is null or absent; anything else must be a finite number.
bool is_value_or_null(const nlohmann::json& v) {
  return v.is_null() || (v.is_number() && std::isfinite(v.get<double>()));
}

}  // namespace

std::vector<Station> parse_stations(const nlohmann::json& artifact, const std::string& where) {
  if (!artifact.is_object() || !artifact.contains("stations") || !artifact["stations"].is_array())
    throw Error(where + ": not a stations artifact (no 'stations' array)");
  std::vector<Station> out;
  for (const auto& s : artifact["stations"]) {
    std::string at = where + ": station " + std::to_string(out.size() + 1);
    if (!s.is_object()) throw Error(at + ": not an object");
    Station st;
    st.id = std::to_string(out.size() + 1);
    if (s.contains("id") && s["id"].is_string()) {
      st.id = s["id"].get<std::string>();
      at += " ('" + st.id + "')";
    }
    st.lon = coordinate(s, "lon", -180, 180, at);
    st.lat = coordinate(s, "lat", -90, 90, at);
    const nlohmann::json elevation = s.value("elevation", nlohmann::json());
    if (!is_value_or_null(elevation))
      throw Error(at + ": elevation " + shown(elevation) + " is not a finite number or null");
    if (!elevation.is_null()) st.elevation = elevation.get<double>();
    st.values = s.value("values", nlohmann::json::object());
    if (!st.values.is_object()) throw Error(at + ": 'values' is not an object");
    for (const auto& [column, v] : st.values.items())
      if (!is_value_or_null(v))
        throw Error(at + ": column '" + column + "': " + shown(v) +
                    " is not a finite number or null");
    out.push_back(std::move(st));
  }
  return out;
}

std::optional<double> station_value(const Station& s, const std::string& column) {
  const auto it = s.values.find(column);
  if (it == s.values.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

}  // namespace maquette::climate
