// climate.regionalize (cell): applies the station fit of climate.fit_stations to a DEM, giving
// temperature and precipitation rasters. Each pixel takes the regression of the first zone
// holding its centre; pixels in no zone, or without elevation, are NaN.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/halo.h"
#include "operators.h"
#include "runtime/params_schema.h"
#include "station_fit.h"
#include "store_inputs.h"

namespace maquette::climate {
namespace {

const std::string kOp = "climate.regionalize";

OperatorSpec regionalize_spec() {
  OperatorSpec s;
  s.name = kOp;
  s.description =
      "Temperature and precipitation from a DEM and the per-zone station regressions of "
      "climate.fit_stations";
  s.inputs = {single_channel_input("dem", "elevation in metres", Semantics::Continuous)};
  s.outputs = {
      {"temperature", "regionalized temperature column", DType::F32, 1, Semantics::Continuous,
       "degC", std::nullopt},
      {"precipitation", "regionalized precipitation column", DType::F32, 1, Semantics::Continuous,
       "mm", std::nullopt},
  };
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"fit"}},
      {"properties",
       {{"fit", named_param(NamedKind::Artifact, std::nullopt,
                            "artifact of climate.fit_stations in the store")},
        {"temperature_column", string_param("", "fitted column for output 'temperature'")},
        {"precipitation_column", string_param("", "fitted column for output 'precipitation'")}}}};
  return s;
}

class Regionalize : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const json& p = *ctx.params;
    const std::string name = p.at("fit").get<std::string>();
    const StationFit fit =
        StationFit::from_json(read_json_artifact(run_store(ctx.store, kOp), name, kOp, "fit"),
                              kOp + ": params.fit: artifact '" + name + "'");
    const Tile<float>& dem = data.input("dem");
    const int size = ctx.tile_size, level = ctx.cell.level() + log2_tile_size(size);
    struct Target {
      Tile<float>* tile;
      std::string column;
      double floor;  // precipitation cannot be negative: a regression extrapolated below the
                     // stations' elevations can be
    };
    std::vector<Target> targets;
    for (const char* port : {"temperature", "precipitation"}) {
      if (!data.wants(port)) continue;
      const std::string field = std::string(port) + "_column";
      const std::string column = p.at(field).get<std::string>();
      if (column.empty())
        throw Error(kOp + ": params." + field + ": output '" + port +
                    "' is mapped but no column is given");
      if (!fit.fits.empty() && !fit.fits.front().count(column))
        throw Error(kOp + ": params." + field + ": column '" + column + "' is not in fit '" + name +
                    "'");
      targets.push_back(
          {&(data.output(port) = Tile<float>(size, 1, 0, std::numeric_limits<float>::quiet_NaN())),
           column, port == std::string("precipitation") ? 0.0 : -HUGE_VAL});
    }
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const double z = dem.at(col, row);
        if (std::isnan(z)) continue;
        const LonLat c = pixel_centre(
            *ctx.grid,
            {ctx.cell.face(), global_col(ctx.cell, size, col), global_row(ctx.cell, size, row)},
            level);
        const int zone = zone_of(fit.zones, c);
        if (zone < 0) continue;
        for (const Target& t : targets)
          t.tile->at(col, row) = float(
              std::max(t.floor, fit.fits[size_t(zone)].at(t.column).predict(c.lon, c.lat, z)));
      }
  }

 private:
  OperatorSpec spec_ = regionalize_spec();
};

}  // namespace

std::unique_ptr<Operator> make_regionalize() { return std::make_unique<Regionalize>(); }

}  // namespace maquette::climate
