#include "stations.h"

#include "core/error.h"

namespace maquette::climate {

std::vector<Station> parse_stations(const nlohmann::json& artifact, const std::string& where) {
  if (!artifact.is_object() || !artifact.contains("stations") || !artifact["stations"].is_array())
    throw Error(where + ": not a stations artifact (no 'stations' array)");
  std::vector<Station> out;
  for (const auto& s : artifact["stations"]) {
    const std::string at = where + ": station " + std::to_string(out.size() + 1);
    if (!s.is_object() || !s.contains("lon") || !s["lon"].is_number() || !s.contains("lat") ||
        !s["lat"].is_number())
      throw Error(at + ": no numeric 'lon' and 'lat'");
    Station st;
    st.id = s.contains("id") && s["id"].is_string() ? s["id"].get<std::string>()
                                                    : std::to_string(out.size() + 1);
    st.lon = s["lon"].get<double>();
    st.lat = s["lat"].get<double>();
    if (s.contains("elevation") && s["elevation"].is_number())
      st.elevation = s["elevation"].get<double>();
    st.values = s.value("values", nlohmann::json::object());
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
