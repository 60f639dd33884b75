// climate.orographic (cell): windward enhancement and lee rain shadow of a precipitation field.
// Air reaching a pixel has come along the wind over the terrain upwind; what it was lifted by
// is the pixel's height above the exponentially weighted mean of the upwind terrain,
//
//   lift(x) = h(x) - sum_k w_k h(x - t_k u) / sum_k w_k,   w_k = exp(-t_k / L),
//
// (t_k = 0, 1, 2... steps of at most one pixel up to the maximum distance, u the direction
// the wind comes from), and
//
//   P'(x) = P(x) * max(0, 1 + strength * lift(x) / 1000 m).
//
// lift > 0 on windward slopes (more rain), < 0 in the lee (less). Mass balance: since the
// weights are normalised, summing lift over a domain that holds the relief and its upwind
// reach, with equal base heights, gives zero (each height enters the means with total weight
// one), so for a uniform P the adjustment only moves precipitation (no clamping at 0).
#include <cmath>
#include <limits>

#include "local_frame.h"
#include "operators.h"
#include "runtime/input_halo.h"
#include "runtime/params_schema.h"

namespace maquette::climate {
namespace {

constexpr int kHalo = 64;
const std::string kOp = "climate.orographic";

OperatorSpec orographic_spec() {
  OperatorSpec s;
  s.name = kOp;
  s.description =
      "Precipitation adjusted for windward lift and lee rain shadow along a main wind direction "
      "(linear upslope model with an exponential upwind memory, 64-pixel halo)";
  s.inputs = {single_channel_input("dem", "elevation in metres", Semantics::Continuous),
              {"precipitation", "precipitation before the adjustment", false}};
  s.outputs = {{"precipitation", "adjusted precipitation", DType::F32, 1, Semantics::Continuous,
                "mm", std::nullopt},
               {"lift", "height above the weighted upwind terrain", DType::F32, 1,
                Semantics::Continuous, "m", std::nullopt}};
  s.halo = kHalo;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"wind_direction",
         number_param(0, 360, 270, "direction the wind comes from, degrees clockwise from north")},
        {"strength", number_param(0, 100, 0.5, "fractional precipitation change per km of lift")},
        {"decay_length", number_param(1, 1e7, 10000, "upwind memory length L, metres")},
        {"max_distance", number_param(0, 1e7, 50000, "upwind reach, metres; at most the halo")}}}};
  return s;
}

class Orographic : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& dem = input_with_halo(kOp, ctx, data, "dem", kHalo);
    const Tile<float>& rain = data.input("precipitation");
    const int size = ctx.tile_size;
    const json& p = *ctx.params;
    const double wind = p.at("wind_direction").get<double>();
    const double strength = p.at("strength").get<double>();
    const double decay = p.at("decay_length").get<double>();
    const double reach = p.at("max_distance").get<double>();

    const float nan = std::numeric_limits<float>::quiet_NaN();
    Tile<float>* out = data.wants("precipitation")
                           ? &(data.output("precipitation") = Tile<float>(size, 1, 0, nan))
                           : nullptr;
    Tile<float>* lift_out =
        data.wants("lift") ? &(data.output("lift") = Tile<float>(size, 1, 0, nan)) : nullptr;
    const LocalFrames frames(*ctx.grid, ctx.cell, size);
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const double h = dem.at(col, row);
        const PixelFrame& f = frames.at(col, row);
        if (std::isnan(h) || !f.valid) continue;
        const March m = march(f, wind);
        // The pixel itself, from its sample: at the edge of the data, bilinear() of even an
        // integer position reads the NaN beyond it.
        double sum = h, weights = 1;
        for (int k = 1; k * m.metres <= reach; ++k) {
          const double z = bilinear(dem, col + k * m.dcol, row + k * m.drow);
          if (std::isnan(z)) break;  // the upwind reach ends at the halo or at no data
          const double w = std::exp(-k * m.metres / decay);
          sum += w * z;
          weights += w;
        }
        const double lift = h - sum / weights;
        if (lift_out) lift_out->at(col, row) = float(lift);
        if (out)
          out->at(col, row) = float(rain.at(col, row) * std::max(0.0, 1 + strength * lift / 1000));
      }
  }

 private:
  OperatorSpec spec_ = orographic_spec();
};

}  // namespace

std::unique_ptr<Operator> make_orographic() { return std::make_unique<Orographic>(); }

}  // namespace maquette::climate
