#include "station_fit.h"

#include <cmath>

#include "core/error.h"
#include "regression.h"

namespace maquette::climate {
namespace {

constexpr double kKmPerDegree = 6371.0088 * M_PI / 180;
constexpr int kFormatVersion = 1;

double east_km(double lon, double lon0, double lat0) {
  return (lon - lon0) * std::cos(lat0 * M_PI / 180) * kKmPerDegree;
}
double north_km(double lat, double lat0) { return (lat - lat0) * kKmPerDegree; }

ColumnFit fit_column(const std::vector<const Station*>& in_zone, const std::string& column,
                     Horizontal h, const std::string& where) {
  ColumnFit fit;
  std::vector<const Station*> used;
  for (const Station* s : in_zone)
    if (s->elevation && station_value(*s, column)) used.push_back(s);
  fit.missing = int64_t(in_zone.size() - used.size());
  fit.stations = int64_t(used.size());
  const bool we = h == Horizontal::WestEast || h == Horizontal::Both;
  const bool sn = h == Horizontal::SouthNorth || h == Horizontal::Both;
  const int k = 2 + int(we) + int(sn);
  if (fit.stations < k + 1)
    throw Error(where + ": column '" + column + "': " + std::to_string(fit.stations) +
                " stations with a value and an elevation, the regression needs at least " +
                std::to_string(k + 1));
  for (const Station* s : used) {
    fit.lon0 += s->lon / double(used.size());
    fit.lat0 += s->lat / double(used.size());
  }
  std::vector<double> design, observed;
  for (const Station* s : used) {
    design.push_back(1);
    design.push_back(*s->elevation / 1000);
    if (we) design.push_back(east_km(s->lon, fit.lon0, fit.lat0));
    if (sn) design.push_back(north_km(s->lat, fit.lat0));
    observed.push_back(*station_value(*s, column));
  }
  const LeastSquares ls = least_squares(design, k, observed);
  if (!ls.full_rank)
    throw Error(where + ": column '" + column +
                "': the stations do not determine the regression (same elevation or position)");
  fit.intercept = ls.coefficients[0];
  fit.per_km_elevation = ls.coefficients[1];
  if (we) fit.per_km_east = ls.coefficients[2];
  if (sn) fit.per_km_north = ls.coefficients[size_t(k - 1)];
  fit.rmse = ls.rmse;
  fit.r2 = ls.r2;
  for (size_t i = 0; i < used.size(); ++i) fit.residuals.emplace_back(used[i]->id, ls.residuals[i]);
  return fit;
}

nlohmann::json column_json(const ColumnFit& f) {
  nlohmann::json residuals = nlohmann::json::array();
  for (const auto& [id, r] : f.residuals) residuals.push_back({{"id", id}, {"residual", r}});
  return {{"stations", f.stations},
          {"missing", f.missing},
          {"reference", {f.lon0, f.lat0}},
          {"coefficients",
           {{"intercept", f.intercept},
            {"per_km_elevation", f.per_km_elevation},
            {"per_km_east", f.per_km_east},
            {"per_km_north", f.per_km_north}}},
          {"rmse", f.rmse},
          {"r2", f.r2},
          {"residuals", std::move(residuals)}};
}

ColumnFit column_from_json(const nlohmann::json& j) {
  ColumnFit f;
  f.stations = j.at("stations").get<int64_t>();
  f.missing = j.at("missing").get<int64_t>();
  f.lon0 = j.at("reference").at(0).get<double>();
  f.lat0 = j.at("reference").at(1).get<double>();
  const auto& c = j.at("coefficients");
  f.intercept = c.at("intercept").get<double>();
  f.per_km_elevation = c.at("per_km_elevation").get<double>();
  f.per_km_east = c.at("per_km_east").get<double>();
  f.per_km_north = c.at("per_km_north").get<double>();
  f.rmse = j.at("rmse").get<double>();
  f.r2 = j.at("r2").get<double>();
  for (const auto& r : j.at("residuals"))
    f.residuals.emplace_back(r.at("id").get<std::string>(), r.at("residual").get<double>());
  return f;
}

}  // namespace

Horizontal parse_horizontal(const std::string& name) {
  if (name == "none") return Horizontal::None;
  if (name == "west_east") return Horizontal::WestEast;
  if (name == "south_north") return Horizontal::SouthNorth;
  if (name == "both") return Horizontal::Both;
  throw Error("unknown horizontal gradient '" + name + "' (none, west_east, south_north, both)");
}

std::string horizontal_name(Horizontal h) {
  static const char* const names[] = {"none", "west_east", "south_north", "both"};
  return names[int(h)];
}

double ColumnFit::predict(double lon, double lat, double elevation_m) const {
  return intercept + per_km_elevation * elevation_m / 1000 +
         per_km_east * east_km(lon, lon0, lat0) + per_km_north * north_km(lat, lat0);
}

nlohmann::json StationFit::to_json() const {
  nlohmann::json zs = nlohmann::json::array();
  for (size_t i = 0; i < zones.size(); ++i) {
    nlohmann::json z = zone_to_json(zones[i]);
    for (const auto& [column, fit] : fits[i]) z["fits"][column] = column_json(fit);
    zs.push_back(std::move(z));
  }
  return {{"kind", "climate.station_fit"},  {"version", kFormatVersion},
          {"stations", stations},           {"horizontal", horizontal_name(horizontal)},
          {"outside_zones", outside_zones}, {"zones", std::move(zs)}};
}

StationFit StationFit::from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || j.value("kind", "") != "climate.station_fit")
    throw Error(where + ": not a station fit of climate.fit_stations");
  if (j.value("version", 0) != kFormatVersion)
    throw Error(where + ": station fit version " + j.value("version", nlohmann::json()).dump() +
                ", this module reads version " + std::to_string(kFormatVersion));
  StationFit f;
  f.stations = j.at("stations").get<std::string>();
  f.horizontal = parse_horizontal(j.at("horizontal").get<std::string>());
  f.outside_zones = j.at("outside_zones").get<int64_t>();
  for (const auto& z : j.at("zones")) {
    f.zones.push_back(zone_from_json(z));
    auto& columns = f.fits.emplace_back();
    for (const auto& [column, fit] : z.at("fits").items()) columns[column] = column_from_json(fit);
  }
  return f;
}

StationFit fit_stations(const std::vector<Station>& stations, std::vector<Zone> zones,
                        const std::vector<std::string>& columns, Horizontal horizontal,
                        const std::string& where) {
  StationFit out;
  out.horizontal = horizontal;
  out.zones = std::move(zones);
  std::vector<std::vector<const Station*>> members(out.zones.size());
  for (const Station& s : stations) {
    const int z = zone_of(out.zones, {s.lon, s.lat});
    if (z < 0)
      ++out.outside_zones;
    else
      members[size_t(z)].push_back(&s);
  }
  for (size_t z = 0; z < out.zones.size(); ++z) {
    auto& fits = out.fits.emplace_back();
    for (const std::string& column : columns)
      fits[column] =
          fit_column(members[z], column, horizontal, where + ": zone '" + out.zones[z].name + "'");
  }
  return out;
}

}  // namespace maquette::climate
