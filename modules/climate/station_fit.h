// Regionalization of station values (paper 5.1): per zone and value column, the least-squares
// regression
//
//   value = intercept + per_km_elevation * z/1000 + per_km_east * x + per_km_north * y
//
// with z the elevation in metres and x, y the kilometres east and north of the reference point
// (the mean lon/lat of the stations fitted; x = (lon - lon0) * cos(lat0) * 111.195 km,
// y = (lat - lat0) * 111.195 km on the mean sphere). The horizontal terms are optional.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "stations.h"
#include "zones.h"

namespace maquette::climate {

enum class Horizontal { None, WestEast, SouthNorth, Both };
Horizontal parse_horizontal(const std::string& name);  // "none", "west_east", ...
std::string horizontal_name(Horizontal h);

struct ColumnFit {
  int64_t stations = 0;  // fitted
  int64_t missing = 0;   // in the zone but without this value or an elevation
  double lon0 = 0, lat0 = 0;
  double intercept = 0, per_km_elevation = 0, per_km_east = 0, per_km_north = 0;
  double rmse = 0, r2 = 0;
  std::vector<std::pair<std::string, double>> residuals;  // station id, observed - fitted

  double predict(double lon, double lat, double elevation_m) const;
};

struct StationFit {
  std::string stations;  // artifact name
  Horizontal horizontal = Horizontal::None;
  std::vector<Zone> zones;
  std::vector<std::map<std::string, ColumnFit>> fits;  // per zone, by column
  int64_t outside_zones = 0;                           // stations in no zone

  nlohmann::json to_json() const;
  // Throws maquette::Error prefixed with `where` for another document.
  static StationFit from_json(const nlohmann::json& j, const std::string& where);
};

// Fits every zone and column; throws maquette::Error prefixed with `where` for a zone with too
// few stations (fewer than the coefficients + 1) or a degenerate design (e.g. one elevation).
StationFit fit_stations(const std::vector<Station>& stations, std::vector<Zone> zones,
                        const std::vector<std::string>& columns, Horizontal horizontal,
                        const std::string& where);

}  // namespace maquette::climate
