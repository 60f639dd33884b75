// Station records of a stations artifact (`maquette ingest --as stations`, see
// formats/vector/README.md): position, elevation and values by column (null: missing).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace maquette::climate {

struct Station {
  std::string id;  // the id column, else the 1-based position in the artifact
  double lon = 0, lat = 0;
  std::optional<double> elevation;  // metres
  nlohmann::json values;            // column -> number or null
};

// Throws maquette::Error prefixed with `where`, naming the station and field, for a document that
// is not a stations artifact, a lon/lat that is not a number within [-180, 180] x [-90, 90], or an
// elevation or value that is neither a finite number nor null (null or absent: missing).
std::vector<Station> parse_stations(const nlohmann::json& artifact, const std::string& where);

// The value of `column` at a station; nullopt when null or absent.
std::optional<double> station_value(const Station& s, const std::string& column);

}  // namespace maquette::climate
