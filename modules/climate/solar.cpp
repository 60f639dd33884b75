// climate.solar: potential direct solar radiation summed over a period (Wh/m^2), with cast
// shadows from horizon angles computed over the halo.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "horizon.h"
#include "local_frame.h"
#include "operators.h"
#include "runtime/params_schema.h"
#include "sun.h"

namespace maquette::climate {
namespace {

constexpr int kHalo = 64;

OperatorSpec solar_spec() {
  OperatorSpec s;
  s.name = "climate.solar";
  s.description =
      "Potential direct solar radiation summed over days of the year (Wh/m^2) from the DEM's "
      "slope and aspect, latitude, solar constant and atmospheric transmissivity, with cast "
      "shadows (horizon angles over a 64-pixel halo)";
  s.inputs = {{"dem", "elevation in metres", false}};
  s.outputs = {{"radiation", "potential direct radiation summed over the period", DType::F32, 1,
                Semantics::Continuous, "Wh/m2", std::nullopt}};
  s.halo = kHalo;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"solar_constant", number_param(0, 2000, 1367, "W/m^2 at the mean sun distance")},
        {"transmissivity",
         number_param(0.01, 1, 0.7,
                      "fraction of the beam passing a vertical sea-level atmosphere")},
        {"first_day", integer_param(1, 366, 1, "first day of year of the period")},
        {"last_day", integer_param(1, 366, 365, "last day of year of the period (inclusive)")},
        {"day_step", integer_param(1, 366, 5, "sample every n-th day (each stands for n days)")},
        {"minutes", number_param(1, 60, 15, "time step within a day")},
        {"max_shadow_distance",
         number_param(0, 1e6, 20000,
                      "metres searched for shadowing terrain (0: no shadows); at most "
                      "the 64-pixel halo")},
        {"horizon_directions", integer_param(4, 360, 36, "azimuths of the horizon angles")}}}};
  return s;
}

SolarOptions options(const json& p) {
  SolarOptions o;
  o.solar_constant = p.at("solar_constant").get<double>();
  o.transmissivity = p.at("transmissivity").get<double>();
  o.first_day = p.at("first_day").get<int>();
  o.last_day = p.at("last_day").get<int>();
  o.day_step = p.at("day_step").get<int>();
  o.minutes = p.at("minutes").get<double>();
  if (o.last_day < o.first_day)
    throw Error("climate.solar: params.last_day: " + std::to_string(o.last_day) +
                " is before first_day " + std::to_string(o.first_day));
  return o;
}

class Solar : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& dem = data.input("dem");
    const int size = ctx.tile_size;
    if (dem.halo() < kHalo || dem.size() != size)
      throw Error("climate.solar: input 'dem' of cell " + ctx.cell.ToText() + " needs a halo of " +
                  std::to_string(kHalo) + " pixels and tile size " + std::to_string(size));
    const json& p = *ctx.params;
    const SolarOptions o = options(p);
    const std::vector<SunSample> sun = sun_samples(o);
    const double distance = p.at("max_shadow_distance").get<double>();
    const HorizonAngles horizons(p.at("horizon_directions").get<int>(), distance);

    Tile<float>& out = data.output("radiation") =
        Tile<float>(size, 1, 0, std::numeric_limits<float>::quiet_NaN());
    const LocalFrames frames(*ctx.grid, ctx.cell, size);
    std::vector<double> angles;
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        Gradient g;
        const double z = dem.at(col, row);
        if (std::isnan(z) || !frames.gradient(dem, col, row, g)) continue;
        const PixelFrame& f = frames.at(col, row);
        Horizon horizon;
        if (distance > 0) {
          horizons.compute(dem, f, col, row, z, angles);
          horizon = {[&](double azimuth) { return horizons.at(angles, azimuth); },
                     *std::max_element(angles.begin(), angles.end())};
        }
        out.at(col, row) = float(potential_radiation(sun, o, f.lat, g.east, g.north, z,
                                                     distance > 0 ? &horizon : nullptr));
      }
  }

 private:
  OperatorSpec spec_ = solar_spec();
};

}  // namespace

std::unique_ptr<Operator> make_solar() { return std::make_unique<Solar>(); }

}  // namespace maquette::climate
