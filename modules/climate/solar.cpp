// climate.solar: potential direct solar radiation summed over a period (Wh/m^2), with cast
// shadows from horizon angles computed over the halo.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "horizon.h"
#include "local_frame.h"
#include "operators.h"
#include "runtime/input_halo.h"
#include "runtime/params_schema.h"
#include "sun.h"

namespace maquette::climate {
namespace {

constexpr int kHalo = 64;

SolarOptions options(const json& p);

OperatorSpec solar_spec() {
  OperatorSpec s;
  s.name = "climate.solar";
  s.description =
      "Potential direct solar radiation summed over days of the year (Wh/m^2) from the DEM's "
      "slope and aspect, latitude, solar constant and atmospheric transmissivity, with cast "
      "shadows (horizon angles over a 64-pixel halo)";
  s.inputs = {single_channel_input("dem", "elevation in metres", Semantics::Continuous)};
  s.outputs = {{"radiation", "potential direct radiation summed over the period", DType::F32, 1,
                Semantics::Continuous, "Wh/m2", std::nullopt}};
  s.halo = kHalo;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"solar_constant", number_param(0, 2000, 1367, "W/m^2 at the mean sun distance")},
        {"atmosphere",
         {{"type", "string"},
          {"enum", {"transmissivity", "linke"}},
          {"default", "transmissivity"},
          {"description",
           "beam attenuation: transmissivity ^ air mass, or GRASS r.sun's clear-sky beam "
           "(Linke turbidity)"}}},
        {"transmissivity",
         number_param(0.01, 1, 0.7,
                      "atmosphere transmissivity: fraction of the beam passing a vertical "
                      "sea-level atmosphere")},
        {"linke_turbidity",
         number_param(0.5, 10, 3, "atmosphere linke: Linke turbidity factor (r.sun's default 3)")},
        {"first_day", integer_param(1, 366, 1, "first day of year of the period")},
        {"last_day", integer_param(1, 366, 365, "last day of year of the period (inclusive)")},
        {"day_step", integer_param(1, 366, 5, "sample every n-th day (each stands for n days)")},
        {"minutes", number_param(1, 60, 15, "time step within a day")},
        {"max_shadow_distance",
         number_param(0, 1e6, 20000,
                      "metres searched for shadowing terrain (0: no shadows); at most "
                      "the 64-pixel halo")},
        {"horizon_directions", integer_param(4, 360, 36, "azimuths of the horizon angles")}}}};
  s.check_params = [](const json& p, const std::set<std::string>&) { options(p); };
  return s;
}

SolarOptions options(const json& p) {
  SolarOptions o;
  o.solar_constant = p.at("solar_constant").get<double>();
  o.atmosphere = p.at("atmosphere") == "linke" ? Atmosphere::Linke : Atmosphere::Transmissivity;
  o.transmissivity = p.at("transmissivity").get<double>();
  o.linke_turbidity = p.at("linke_turbidity").get<double>();
  o.first_day = p.at("first_day").get<int>();
  o.last_day = p.at("last_day").get<int>();
  o.day_step = p.at("day_step").get<int>();
  o.minutes = p.at("minutes").get<double>();
  if (o.last_day < o.first_day)
    throw Error("climate.solar: params.last_day: " + std::to_string(o.last_day) +
                " is before first_day " + std::to_string(o.first_day));
  return o;
}

// The frame a block's marches use: its centre pixel's, or the first valid one of its pixels.
const PixelFrame& block_frame(const LocalFrames& frames, int col0, int row0) {
  const int B = HorizonAngles::kBlock;
  const PixelFrame& centre = frames.at(col0 + B / 2, row0 + B / 2);
  if (centre.valid) return centre;
  for (int r = 0; r < B; ++r)
    for (int c = 0; c < B; ++c)
      if (frames.at(col0 + c, row0 + r).valid) return frames.at(col0 + c, row0 + r);
  return centre;
}

class Solar : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& dem = input_with_halo("climate.solar", ctx, data, "dem", kHalo);
    const int size = ctx.tile_size;
    const json& p = *ctx.params;
    const SolarModel model(options(p));
    const double distance = p.at("max_shadow_distance").get<double>();
    const HorizonAngles horizons(p.at("horizon_directions").get<int>(), distance);

    Tile<float>& out = data.output("radiation") =
        Tile<float>(size, 1, 0, std::numeric_limits<float>::quiet_NaN());
    const LocalFrames frames(*ctx.grid, ctx.cell, size);
    // Only the directions the sun takes over the period: those at the latitudes of the tile's
    // corners and centre, and one more on either side for the latitudes between them.
    std::vector<char> used(size_t(horizons.directions()), 0);
    for (const auto& [col, row] : {std::pair{0, 0},
                                   {size - 1, 0},
                                   {0, size - 1},
                                   {size - 1, size - 1},
                                   {size / 2, size / 2}})
      if (frames.at(col, row).valid) model.mark_directions(frames.at(col, row).lat, used);
    std::vector<char> padded = used;
    const int n = horizons.directions();
    for (int k = 0; k < n; ++k)
      if (used[size_t(k)]) padded[size_t((k + 1) % n)] = padded[size_t((k + n - 1) % n)] = 1;
    used = padded;
    float zmax = -INFINITY;
    for (const float z : dem.data())
      if (z > zmax) zmax = z;  // NaN compares false
    const DilatedDem surfaces(dem, distance > 0 ? HorizonAngles::kLevels : 0);
    // Blocks in parallel: each pixel is computed alone, so the bits do not depend on threads.
    const int B = HorizonAngles::kBlock, blocks = size / B;
    tbb::parallel_for(0, blocks * blocks, [&](int block) {
      const int col0 = block % blocks * B, row0 = block / blocks * B;
      std::vector<float> angles;
      if (distance > 0)
        horizons.compute(surfaces, zmax, used, block_frame(frames, col0, row0), col0, row0, angles);
      const int n = horizons.directions();
      for (int r = 0; r < B; ++r)
        for (int c = 0; c < B; ++c) {
          const int col = col0 + c, row = row0 + r;
          Gradient g;
          const double z = dem.at(col, row);
          if (std::isnan(z) || !frames.gradient(dem, col, row, g)) continue;
          Horizon horizon;
          if (distance > 0) {
            const std::span<const float> pixel(&angles[size_t(r * B + c) * size_t(n)], size_t(n));
            horizon = {pixel, *std::max_element(pixel.begin(), pixel.end())};
          }
          out.at(col, row) = float(model.radiation(frames.at(col, row).lat, g.east, g.north, z,
                                                   distance > 0 ? &horizon : nullptr));
        }
    });
  }

 private:
  OperatorSpec spec_ = solar_spec();
};

}  // namespace

std::unique_ptr<Operator> make_solar() { return std::make_unique<Solar>(); }

}  // namespace maquette::climate
