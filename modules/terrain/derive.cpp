// terrain.derive: slope, aspect, profile curvature, hillshade and normals of a DEM, in true
// metres on the ellipsoid (see core/tile_frame.h, neighbourhood.h and surface_fit.h).
#include <cmath>
#include <limits>

#include "neighbourhood.h"
#include "operators.h"
#include "runtime/input_halo.h"
#include "runtime/params_schema.h"
#include "surface_fit.h"
#include "surface_measures.h"

namespace maquette::terrain {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

OperatorSpec derive_spec() {
  OperatorSpec s;
  s.name = "terrain.derive";
  s.description =
      "Slope, aspect, profile curvature, hillshade and surface normals of a DEM, with metric "
      "scale from the true cell geometry (seamless across faces)";
  s.kind = OperatorKind::Cell;
  s.inputs = {single_channel_input("dem", "elevation in metres", Semantics::Continuous)};
  s.outputs = {
      {"slope", "slope angle", DType::F32, 1, Semantics::Continuous, "degrees", std::nullopt},
      {"aspect", "direction of steepest descent, clockwise from north; NaN where flat", DType::F32,
       1, Semantics::Continuous, "degrees", std::nullopt},
      {"curvature", "profile curvature, positive where convex; NaN where flat", DType::F32, 1,
       Semantics::Continuous, "1/m", std::nullopt},
      {"hillshade", "1 + 254 * cos(incidence) clamped at 1 (0 = nodata)", DType::U8, 1,
       Semantics::Continuous, "", 0.0},
      {"normal", "unit surface normal, east-north-up", DType::F32, 3, Semantics::Continuous, "",
       std::nullopt, "normal_oct"},
  };
  s.halo = 1;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"azimuth",
         number_param(0, 360, 315, "hillshade light direction, degrees clockwise from north")},
        {"altitude",
         number_param(0, 90, 45, "hillshade light altitude, degrees above the horizon")},
        {"z_factor",
         {{"type", "number"},
          {"minimum", 0},
          {"default", 1},
          {"description", "hillshade vertical exaggeration"}}}}}};
  return s;
}

class Derive : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& dem = input_with_halo("terrain.derive", ctx, data, "dem", 1);
    const int size = ctx.tile_size;
    const json& params = *ctx.params;
    const Light light{params.at("azimuth").get<double>(), params.at("altitude").get<double>(),
                      params.at("z_factor").get<double>()};

    // Only the outputs the step maps are computed.
    Tile<float>* slope = output(data, "slope", size, 1);
    Tile<float>* aspect = output(data, "aspect", size, 1);
    Tile<float>* curvature = output(data, "curvature", size, 1);
    Tile<float>* shade = output(data, "hillshade", size, 1);
    Tile<float>* normal = output(data, "normal", size, 3);

    const TileFrame frame(*ctx.grid, ctx.cell, size);
    Neighbourhood offsets;
    Heights h;
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        if (!heights(dem, col, row, h) || !neighbourhood(frame, col, row, offsets)) continue;
        const Gradient g = fit_gradient(offsets, h);
        if (slope) slope->at(col, row) = float(slope_degrees(g));
        if (aspect) aspect->at(col, row) = float(aspect_degrees(g));
        if (shade) shade->at(col, row) = float(hillshade(g, light));
        if (normal) {
          const std::array<double, 3> n = normal_enu(g);
          for (int k = 0; k < 3; ++k) normal->at(col, row, k) = float(n[k]);
        }
        if (curvature)
          curvature->at(col, row) = float(profile_curvature(fit_quadratic(offsets, h)));
      }
  }

 private:
  static Tile<float>* output(CellData& data, const std::string& port, int size, int channels) {
    if (!data.wants(port)) return nullptr;
    return &(data.output(port) = Tile<float>(size, channels, 0, kNaN));
  }

  // The 3x3 heights around (col, row); false when one is NaN.
  static bool heights(const Tile<float>& dem, int col, int row, Heights& h) {
    for (int i = 0; i < 9; ++i) {
      h[i] = dem.at(col + i % 3 - 1, row + i / 3 - 1);
      if (std::isnan(h[i])) return false;
    }
    return true;
  }

  OperatorSpec spec_ = derive_spec();
};

}  // namespace

std::unique_ptr<Operator> make_derive() { return std::make_unique<Derive>(); }

}  // namespace maquette::terrain
