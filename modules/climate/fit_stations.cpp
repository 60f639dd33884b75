// climate.fit_stations (reduce): the per-zone regressions of station values on elevation (and
// optionally position), written as the coefficients artifact that climate.regionalize applies.
// The cells only tell which stations lie outside the step's region; the fit is made once, in
// finish().
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/error.h"
#include "core/lonlat_bounds.h"
#include "operators.h"
#include "runtime/params_schema.h"
#include "station_fit.h"
#include "store_inputs.h"

namespace maquette::climate {
namespace {

const std::string kOp = "climate.fit_stations";

OperatorSpec fit_spec() {
  OperatorSpec s;
  s.name = kOp;
  s.description =
      "Per-zone least-squares regressions of station values (stations artifact) on elevation, "
      "optionally with west-east / south-north gradients; writes the coefficients and "
      "residuals as an artifact for climate.regionalize";
  s.kind = OperatorKind::Reduce;
  s.outputs = {{"fit", "station fit artifact (JSON)", DType::F32, 1, Semantics::Continuous, "",
                std::nullopt}};
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"stations", "columns"}},
      {"properties",
       {{"stations",
         named_param(NamedKind::Artifact, std::nullopt, "stations artifact name in the store")},
        {"columns",
         {{"type", "array"},
          {"items", {{"type", "string"}}},
          {"description", "value columns to regress"}}},
        {"zones", named_param(NamedKind::Layer, "",
                              "features layer of zone polygons in the store; empty: one zone")},
        {"zone_field",
         string_param("", "zone attribute naming each zone in the report; empty: the fid")},
        {"horizontal",
         {{"type", "string"},
          {"enum", {"none", "west_east", "south_north", "both"}},
          {"default", "none"},
          {"description", "horizontal gradient terms"}}},
        {"outside_region",
         {{"type", "string"},
          {"enum", {"use", "drop", "error"}},
          {"default", "use"},
          {"description", "stations outside the step's cells: fitted, left out, or an error"}}}}}};
  return s;
}

class FitStations : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  json map(const CellContext& ctx, const CellData&) const override {
    return json::array({ctx.cell.id()});
  }

  json merge(const json& a, const json& b) const override {
    json out = a;
    out.insert(out.end(), b.begin(), b.end());
    return out;
  }

  Artifact finish(const json& merged, const StepContext& ctx) const override {
    const json& params = *ctx.params;
    const Store& store = run_store(ctx.store, kOp);
    const std::string name = params.at("stations").get<std::string>();
    std::vector<Station> stations =
        parse_stations(read_json_artifact(store, name, kOp, "stations"),
                       kOp + ": params.stations: artifact '" + name + "'");
    const std::vector<CellId> region = region_cells(merged);
    check_overlap(stations, region, name);
    const int64_t outside = drop_outside(stations, region, params.at("outside_region"));
    const auto columns = params.at("columns").get<std::vector<std::string>>();
    if (columns.empty()) throw Error(kOp + ": params.columns: no column given");
    check_columns(stations, columns);

    std::vector<Zone> zones;
    if (const std::string layer = params.at("zones"); !layer.empty())
      zones = read_zones(store, layer, params.at("zone_field"), kOp);
    else
      zones.push_back({std::nullopt, "all", {}, {-180, -90, 180, 90}});
    StationFit fit = fit_stations(stations, std::move(zones), columns,
                                  parse_horizontal(params.at("horizontal")), kOp);
    fit.stations = name;
    log(fit, outside);

    json report = fit.to_json();
    report["outside_region"] = outside;
    const std::string text = report.dump();
    return Artifact::FromText(
        "", text, {{"kind", "climate.station_fit"}, {"stations", name}, {"columns", columns}});
  }

 private:
  // The step's cells, sorted (empty for a step without cells).
  static std::vector<CellId> region_cells(const json& merged) {
    std::vector<CellId> region;
    if (merged.is_array())
      for (const auto& id : merged) region.emplace_back(id.get<uint64_t>());
    std::sort(region.begin(), region.end());
    return region;
  }

  // Stations that all lie away from the step's region would give a fit extrapolated onto it
  // from elsewhere (e.g. a DEM of another area): refused. Their bounding box must meet the
  // region's lon/lat bounds; a region only partly covered by the stations is fitted.
  static void check_overlap(const std::vector<Station>& stations, const std::vector<CellId>& region,
                            const std::string& name) {
    if (region.empty() || stations.empty()) return;
    LonLatBounds s{180, 90, -180, -90};
    for (const Station& st : stations) {
      s.west = std::min(s.west, st.lon);
      s.east = std::max(s.east, st.lon);
      s.south = std::min(s.south, st.lat);
      s.north = std::max(s.north, st.lat);
    }
    const LonLatBounds r = lonlat_bounds(default_grid(), region);
    // r.east may exceed 180 (a region across the antimeridian): try the stations shifted by 360.
    const auto meets = [&](double shift) {
      return s.west + shift <= r.east && s.east + shift >= r.west;
    };
    if ((meets(0) || meets(360)) && s.south <= r.north && s.north >= r.south) return;
    const auto box = [](const LonLatBounds& b) {
      return fmt::format("lon {:g}..{:g}, lat {:g}..{:g}", b.west, b.east, b.south, b.north);
    };
    throw Error(kOp + ": params.stations: the " + std::to_string(stations.size()) +
                " stations of '" + name + "' (" + box(s) + ") do not overlap the step's region (" +
                box(r) + "): the fit would be extrapolated from elsewhere");
  }

  // Stations outside the step's cells: counted, and kept, dropped or refused per `policy`.
  static int64_t drop_outside(std::vector<Station>& stations, const std::vector<CellId>& region,
                              const std::string& policy) {
    if (region.empty()) return 0;
    const int level = region.front().level();
    const auto inside = [&](const Station& s) {
      const CellId c = default_grid().cell_from_point({s.lon, s.lat}, level);
      return std::binary_search(region.begin(), region.end(), c);
    };
    std::vector<Station> kept;
    int64_t outside = 0;
    for (Station& s : stations) {
      if (inside(s)) {
        kept.push_back(std::move(s));
        continue;
      }
      ++outside;
      if (policy == "error")
        throw Error(kOp + ": params.outside_region: station " + s.id + " at (" +
                    std::to_string(s.lon) + ", " + std::to_string(s.lat) +
                    ") is outside the step's region");
      if (policy == "use") kept.push_back(std::move(s));
    }
    stations = std::move(kept);
    return outside;
  }

  static void check_columns(const std::vector<Station>& stations,
                            const std::vector<std::string>& columns) {
    for (const std::string& c : columns)
      if (std::none_of(stations.begin(), stations.end(),
                       [&](const Station& s) { return s.values.contains(c); }))
        throw Error(kOp + ": params.columns: no station has a column '" + c + "'");
  }

  static void log(const StationFit& fit, int64_t outside) {
    spdlog::info("{}: {} stations outside the region, {} outside every zone", kOp, outside,
                 fit.outside_zones);
    for (size_t z = 0; z < fit.zones.size(); ++z)
      for (const auto& [column, f] : fit.fits[z])
        spdlog::info(
            "{}: zone '{}' {}: {} stations ({} missing), {:.6g} + {:.6g}/km elevation + {:.6g}/km "
            "east + {:.6g}/km north; rmse {:.4g}, r2 {:.4f}",
            kOp, fit.zones[z].name, column, f.stations, f.missing, f.intercept, f.per_km_elevation,
            f.per_km_east, f.per_km_north, f.rmse, f.r2);
  }

  OperatorSpec spec_ = fit_spec();
};

}  // namespace

std::unique_ptr<Operator> make_fit_stations() { return std::make_unique<FitStations>(); }

}  // namespace maquette::climate
